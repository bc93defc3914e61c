#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset sanitize > /dev/null
cmake --build build-sanitize -j"$(nproc)"
# Mesa, Embree and TBB are not instrumented; their allocations at exit are not ours.
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Full stacks at allocation, so that leaks inside Mesa's JIT are attributed to it.
export ASAN_OPTIONS="fast_unwind_on_malloc=0"
ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" --timeout 1200
