#!/usr/bin/env bash
# Installs Lucent into a scratch prefix, checks that only the public headers are
# installed, builds examples/ against it with find_package(Lucent) as a host
# project would, and runs that host on a scene preprocessed by the installed
# lucent (which must find its own data beside itself, not in a checkout).
set -euo pipefail
build_dir=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
prefix=$scratch/prefix
cmake --install "$build_dir" --prefix "$prefix" > /dev/null

# Public headers only: nothing of runtime/internal, and each public runtime header
# compiles on its own from the installed include directory.
# The Python module, when built, lands in the prefix's dist-packages and finds
# the installed libraries from there (docs/python.md).
module=$(find "$prefix" -path '*dist-packages/lucent*.so' | head -1)
if [ -n "$module" ]; then
  (cd "$scratch" && PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c \
    'import lucent, sys; sys.exit(0 if lucent.__file__.startswith(sys.argv[1]) and lucent.methods() else 1)' "$prefix") ||
    { echo "FAIL: the installed Python module does not import from $module"; exit 1; }
fi
if [ -e "$prefix/include/lucent/runtime/internal" ]; then
  echo "FAIL: the runtime's private headers were installed"; exit 1
fi
for header in "$prefix"/include/lucent/runtime/*.h; do
  echo "#include \"runtime/$(basename "$header")\"" |
    g++ -std=c++20 -fsyntax-only -I"$prefix/include/lucent" -x c++ - ||
    { echo "FAIL: $header does not compile on its own"; exit 1; }
done
# A host that loads OpenGL itself (libepoxy here) includes Lucent's public
# headers after its own GL header: no loader header of Lucent's may come along.
for header in "$prefix"/include/lucent/runtime/*.h; do
  printf '#include <epoxy/gl.h>\n#include "runtime/%s"\n' "$(basename "$header")" |
    g++ -std=c++20 -fsyntax-only -I"$prefix/include/lucent" $(pkg-config --cflags epoxy) -x c++ - ||
    { echo "FAIL: $header does not compile after the host's own GL header"; exit 1; }
done
# No loader symbol of Lucent's meets the host's: every name glad defines is prefixed lucent_.
exported=$(find "$prefix" -name 'liblucent*.a' -exec nm -g --defined-only {} + 2> /dev/null |
  awk 'NF == 3 {print $3}' | grep -E '^(glad|GLAD|gl[A-Z]|epoxy)' || true)
if [ -n "$exported" ]; then
  echo "FAIL: Lucent's libraries export OpenGL loader symbols: $(echo "$exported" | head -3 | tr '\n' ' ')"; exit 1
fi
if [ -e "$prefix/include/lucent/hybrid" ]; then
  [ ! -e "$prefix/include/lucent/hybrid/internal" ] || { echo "FAIL: the hybrid's private headers were installed"; exit 1; }
  echo '#include "hybrid/multiple_scattering.h"' | g++ -std=c++20 -fsyntax-only -I"$prefix/include/lucent" -x c++ - ||
    { echo "FAIL: hybrid/multiple_scattering.h does not compile on its own"; exit 1; }
fi
test -f "$prefix/share/lucent/plot-accuracy.py" || { echo "FAIL: plot-accuracy.py not installed"; exit 1; }

# The host is built as Lucent was (a sanitized Lucent needs a sanitized host to load it).
cxx_flags=$(sed -n 's/^CMAKE_CXX_FLAGS:STRING=//p' "$build_dir/CMakeCache.txt")
link_flags=$(sed -n 's/^CMAKE_EXE_LINKER_FLAGS:STRING=//p' "$build_dir/CMakeCache.txt")
cmake -S "$source_dir/examples" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$link_flags" > /dev/null
cmake --build "$scratch/build" -j2 > /dev/null
test -x "$scratch/build/lucent-example-host"
test -x "$scratch/build/lucent-example-window"

cat > "$scratch/scene.json" <<JSON
{"camera": {"position": [0, 0.6, 5], "target": [0, 0, 0], "fov_y": 35, "width": 32, "height": 32},
 "lights": [{"type": "point", "position": [3, 3, 3], "intensity": [40, 40, 40]}],
 "objects": [{"mesh": "$source_dir/models/sphere.obj", "medium": {"sigma_t": 2.0, "albedo": 0.75}, "samples": "s.lsf"}]}
JSON
"$prefix/bin/lucent" preprocess "$scratch/scene.json" --quality draft --samples 1000 2> /dev/null
"$scratch/build/lucent-example-host" "$scratch/scene.json" "$scratch/out.pfm" --no-occluder 2> "$scratch/host.log" ||
  { echo "FAIL: the example host did not run:"; cat "$scratch/host.log"; exit 1; }
# The host's image: a 32x32 PFM whose brightest pixel is the sphere's light (not 0).
python3 - "$scratch/out.pfm" <<'PY'
import struct, sys
data = open(sys.argv[1], 'rb').read()
header = data.split(b'\n', 3)
assert header[0] == b'PF' and header[1].split() == [b'32', b'32'], header[:2]
pixels = struct.unpack('<%df' % (32 * 32 * 3), header[3])
assert max(pixels) > 0.0, 'black image'
PY
echo "find_package(Lucent) from an installed prefix: public headers only, example host built and run"
