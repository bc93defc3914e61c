#!/usr/bin/env bash
# Installs the Debian 12 packages Lucent builds, runs and tests with.
# Root runs apt-get directly; anyone else goes through sudo.
#   --peer   also Blender, whose Cycles lucent-bench-peer measures Lucent against
#            (a benchmark's peer, never needed by the tests)
set -euo pipefail

peer=0
for arg in "$@"; do
  case "$arg" in
    --peer) peer=1 ;;
    *) echo "install-deps: unknown option '$arg' (known: --peer)" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake pkg-config
  # meshes, ray casting and volumes
  libopenmesh-dev libopenvdb-dev libboost-iostreams-dev libtbb-dev
  # math, parsing, command line
  libembree-dev libeigen3-dev libglm-dev nlohmann-json3-dev libcli11-dev
  # glTF 2.0 scenes (.gltf, .glb)
  libtinygltf-dev
  # the sample file's checksum and the objects' fingerprints
  libxxhash-dev
  # image output
  libpng-dev libopenexr-dev
  # environment maps: Radiance .hdr (stb_image; .exr through OpenEXR above)
  libstb-dev
  # OpenGL: EGL and OSMesa on Mesa's llvmpipe (libgl1-mesa-dri is what EGL needs
  # and nothing depends on), the glad loader generator, GLFW + Dear ImGui for the
  # viewer, Xvfb to test the viewer without a display
  libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev python3-glad libglfw3-dev libimgui-dev xvfb xauth
  # the example hosts load OpenGL themselves (libepoxy), beside Lucent's own loader
  libepoxy-dev
  # OpenCL for the hybrid (hybrid/): headers, the ICD loader and PoCL, which runs
  # the kernels on the CPU; clinfo to see what the loader finds
  opencl-headers opencl-clhpp-headers ocl-icd-opencl-dev pocl-opencl-icd clinfo
  # tests and benchmarks; CGAL's demo meshes for lucent bench accuracy --cgal;
  # clang-format for the style check (Style.ClangFormat)
  libgtest-dev libgmock-dev libbenchmark-dev libcgal-demo clang-format
  # the plots of lucent bench accuracy
  python3-matplotlib
  # MPI: lucent render under mpirun shares an image's rows among ranks (docs/mpi.md)
  libopenmpi-dev openmpi-bin
  # the Python module (python/) and its tests: pybind11 for Debian's python3, numpy, pytest, tqdm
  pybind11-dev python3-dev python3-numpy python3-pytest python3-tqdm
  # the CAD test solids: models/cad/*.scad are exported to closed STL meshes
  openscad
)
if [ "$peer" -eq 1 ]; then packages+=(blender); fi

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
