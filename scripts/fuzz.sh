#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan, UBSan) and runs each for a bounded
# time on its committed corpus under fuzz/corpus/. New interesting inputs are
# added to the corpus; a crash stops the script with the reproducer's path.
#   scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 60)
#   FUZZ_TARGETS="mesh grid" scripts/fuzz.sh 600   (a subset)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
scripts/install-deps.sh
if ! command -v clang++ > /dev/null || [ ! -d /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux ]; then
  if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
  "${sudo[@]}" apt-get install -y -q --no-install-recommends clang libclang-rt-14-dev
fi
cmake --preset fuzz > /dev/null
cmake --build build-fuzz -j"$(nproc)" --target lucent-fuzz-scene lucent-fuzz-sample_file lucent-fuzz-mesh lucent-fuzz-grid lucent-fuzz-gltf
mkdir -p build-fuzz/artifacts
# The leak check at exit knows the libraries' allocations kept until exit as
# the sanitizer suite does (OpenMesh's, reached by the gltf target's meshes).
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/lsan.supp:print_suppressions=0"
for target in ${FUZZ_TARGETS:-scene sample_file mesh grid gltf}; do
  corpus=fuzz/corpus/${target//_/-}
  found=build-fuzz/found-$target
  rm -rf "$found" && mkdir -p "$found"
  # libFuzzer's per-input leak check flags an allocation inside OpenVDB's reader
  # that is freed by exit (valgrind: 0 bytes definitely lost): not Lucent's.
  flags=()
  if [ "$target" = grid ]; then flags=(-detect_leaks=0); fi
  echo "fuzz: lucent-fuzz-$target for ${seconds}s on $corpus"
  build-fuzz/bin/lucent-fuzz-$target -max_total_time="$seconds" -artifact_prefix=build-fuzz/artifacts/ \
    -print_final_stats=1 -rss_limit_mb=8192 "${flags[@]}" "$found" "$corpus"
  # Keep the corpus small: add only inputs that reach new coverage.
  build-fuzz/bin/lucent-fuzz-$target -merge=1 "${flags[@]}" "$corpus" "$found" 2> /dev/null
done
