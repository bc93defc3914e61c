#include "apps/heap_pages.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace lucent {

// On the virtual machines Lucent is measured on, the first write to a page costs
// a fault in the guest and one in the host, and the bunny's 800x800 render
// touched 53 000 pages: about half its time. glibc asks for huge pages only under
// GLIBC_TUNABLES, read when the process starts, so here malloc is steered by hand:
// - every block below 32 MB (the most mallopt allows) comes from the main heap,
//   not from a mapping of its own, and every thread shares that heap (one arena);
// - the heap grows by 256 MB of address space at once, which costs nothing until
//   touched, and is marked MADV_HUGEPAGE;
// - freed memory stays in the heap (no trimming), still on its huge pages.
void serveHeapFromHugePages() {
    constexpr size_t kHugePage = size_t(2) << 20, kPad = size_t(256) << 20, kGrow = size_t(30) << 20;
    if (mallopt(M_ARENA_MAX, 1) != 1 || mallopt(M_MMAP_THRESHOLD, 32 << 20) != 1 ||
        mallopt(M_TRIM_THRESHOLD, 1 << 30) != 1 || mallopt(M_TOP_PAD, int(kPad)) != 1)
        return;
    char* grown = static_cast<char*>(std::malloc(kGrow));  // below the threshold: moves the heap's end
    if (!grown) return;
    char* end = static_cast<char*>(sbrk(0));
    // Only if the block lies in the heap that sbrk grows (another allocator, a
    // sanitizer's say, has its own).
    if (grown < end && size_t(end - grown) <= kGrow + kPad + kHugePage) {
        const uintptr_t from = (reinterpret_cast<uintptr_t>(grown) + kHugePage - 1) & ~(kHugePage - 1);
        const uintptr_t to = reinterpret_cast<uintptr_t>(end) & ~(kHugePage - 1);
        if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
    }
    std::free(grown);
}

}  // namespace lucent
