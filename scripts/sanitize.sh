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
# Every test without OpenGL, with leak checks.
ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" --label-exclude opengl
# The OpenGL tests under ASan and UBSan without leak checks: Mesa dlcloses its
# drivers before the check at exit, so their allocations show as unknown modules
# that no suppression can name, and unwinding through them at every malloc
# instead (fast_unwind_on_malloc=0) deadlocks against the loader's lock.
LSAN_OPTIONS="$LSAN_OPTIONS:detect_leaks=0" \
  ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" --label-regex opengl
