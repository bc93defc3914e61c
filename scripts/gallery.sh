#!/usr/bin/env bash
# The pictures of the docs, made from a build: the README's image of the bundled
# scene (the Stanford bunny, the main job's scene) as `lucent render` draws it
# with --method auto, then docs/gallery.md, every method on the bundled scenes
# beside the path tracer with its error and time (lucent-bench-gallery, through
# --record). Sample files go to a temporary folder; the images to docs/images/.
#   scripts/gallery.sh [--build DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="${2:?--build needs a folder}"; shift 2 ;;
    *) echo "gallery.sh: unknown option '$1' (known: --build DIR)" >&2; exit 2 ;;
  esac
done
lucent="$build/bin/lucent"
[ -x "$lucent" ] || { echo "gallery.sh: error: $lucent: not built (scripts/build.sh)" >&2; exit 1; }
work=$(mktemp -d /tmp/lucent-gallery-XXXXXX)
trap 'rm -rf "$work"' EXIT
cp models/bunny.json models/bunny.off "$work/"
mkdir -p docs/images
"$lucent" preprocess "$work/bunny.json"
"$lucent" render "$work/bunny.json" -o docs/images/bunny.png
echo "gallery.sh: wrote docs/images/bunny.png ($(stat -c %s docs/images/bunny.png) bytes)"
"$build/bin/lucent-bench-gallery" --images docs/images/gallery --record docs/gallery.md
echo "gallery.sh: wrote docs/gallery.md ($(du -cb docs/images/gallery/*.png | tail -1 | cut -f1) bytes of images)"
