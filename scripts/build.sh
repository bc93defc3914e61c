#!/usr/bin/env bash
# Installs the Debian packages Lucent needs (scripts/install-deps.sh), then
# configures and builds everything into build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
