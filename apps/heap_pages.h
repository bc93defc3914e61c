#pragma once

namespace lucent {

// Has malloc serve the process from transparent huge pages (2 MB), which the
// kernel then zeroes and maps one fault at a time instead of 512. Call first
// thing in main, before any thread starts; where it cannot, it does nothing.
// Why and what it measured: docs/runtime.md, "The whole command, and page faults".
void serveHeapFromHugePages();

}  // namespace lucent
