#!/usr/bin/env bash
# The main job on the bundled default scene (the Stanford bunny): install, build,
# preprocess the samples, render. Writes out/bunny.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p out
build/bin/lucent preprocess models/bunny.json
build/bin/lucent info models/bunny.lsf
build/bin/lucent render models/bunny.json -o out/bunny.png
echo "demo: wrote $(pwd)/out/bunny.png"
