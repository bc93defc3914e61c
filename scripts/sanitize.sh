#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset sanitize > /dev/null
cmake --build build-sanitize -j"$(nproc)"

# Every option below is there for one reason, given beside it; none is a retry.
#
# intercept_tls_get_addr=0: GCC 12's sanitizer runtime (as GCC up to 13 and LLVM
#   up to 16) intercepts __tls_get_addr and takes a dynamic TLS block whose start
#   lies at a fixed offset in its page for one with glibc 2.19's header, reading
#   the two words before it as the block's address and size. Since glibc 2.25
#   there is no such header, so whether a test passes depends on where malloc
#   happened to put the TLS of the libraries it loads (PoCL, hwloc's plug-ins,
#   Mesa). When the guess is wrong, LeakSanitizer's tracer reads that garbage
#   range at exit and dies with "Tracer caught signal 11", after the test has
#   passed. Off, the interceptor records nothing, and the dynamic TLS blocks are
#   still found by the leak check as the ordinary heap blocks they are.
# suppressions: Mesa, LLVM, Embree, TBB and the other libraries whose
#   allocations live until exit and are not ours (scripts/lsan.supp).
# print_suppressions=0: the suppressed list is noise in a passing log.
sanitizer_common="intercept_tls_get_addr=0"
export ASAN_OPTIONS="$sanitizer_common"
export LSAN_OPTIONS="$sanitizer_common:suppressions=$(pwd)/scripts/lsan.supp:print_suppressions=0"
# halt_on_error with print_stacktrace: undefined behaviour fails the test, with
# where it happened.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# The accuracy tier stays out: a test whose name says it meets (or is within) a
# goal renders a method's image and the reference at full size to measure the
# error, which the sanitizers cannot change. Its code runs here at test sizes
# in the other tiers; the accuracy tests run in scripts/test.sh. They are about
# a quarter of this suite's time, and CI's goal is under 60 minutes for both
# suites with both builds (docs/results/ci.md).
accuracy_tier='(Meets?|Within)[A-Za-z]*Goal'

# Every other test in one run, so that both cores stay busy to the end. Leak checks
# are on, but for the tests that set LSAN_OPTIONS themselves (tests/CMakeLists.txt,
# LUCENT_NO_LEAK_CHECK):
# - OpenGL (label opengl): Mesa dlcloses its drivers before the check at exit,
#   so their allocations show as unknown modules that no suppression can name,
#   and unwinding through them at every malloc instead (fast_unwind_on_malloc=0)
#   deadlocks against the loader's lock;
# - lucent under mpirun (label mpi): OpenMPI 4.1 itself does not pass them (a
#   program that only calls MPI_Init and MPI_Finalize, built with ASan,
#   reports 121 kB in 3351 allocations per rank).
ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" -E "$accuracy_tier"
