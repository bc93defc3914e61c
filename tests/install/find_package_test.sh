#!/usr/bin/env bash
# Installs Lucent into a scratch prefix and builds examples/ against it with
# find_package(Lucent), as a host project would.
set -euo pipefail
build_dir=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > /dev/null
cmake -S "$source_dir/examples" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$scratch/build" -j2 > /dev/null
test -x "$scratch/build/lucent-example-host"
echo "find_package(Lucent) from an installed prefix: example host built"
