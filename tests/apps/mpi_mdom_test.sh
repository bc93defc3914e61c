#!/usr/bin/env bash
# lucent render --method mdom under mpirun with real ranks (docs/mpi.md): the
# ranks share the sweeps KBA-style, and the image is one process's within 1e-6
# of its brightest pixel on 2, 3 and 4 ranks (process grids 1x2, 1x3 and 2x2)
# for a refracting sphere; on 3 ranks the borders cut its surface, so Fresnel
# mirrors lie on them (found per rank instead, they move the image by 1.3%). A
# grid no rank can hold is one error line and no output; a rank killed while
# the ranks sweep ends the run with no output, never a hang.
#   mpi_mdom_test.sh LUCENT SOURCE_DIR
set -euo pipefail
source "$(dirname "$(realpath "$0")")/mpi_test_setup.sh" "$@"
cp "$source_dir/models/sphere.obj" .

cat > glass.json << 'JSON'
{"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 30, "width": 40, "height": 36},
 "lights": [{"type": "point", "position": [3, 3, 3], "intensity": [40, 40, 40]}],
 "objects": [{"name": "sphere", "mesh": "sphere.obj", "samples": "sphere.lsf",
              "medium": {"sigma_t": 2.0, "albedo": 0.8, "g": 0.5, "ior": 1.4}}],
 "render": {"surface": false}}
JSON
"$lucent" preprocess glass.json --quality draft 2> /dev/null

# The floats of a PFM image, one a line.
floats() { tail -c +$(($(head -3 "$1" | wc -c) + 1)) "$1" | od -An -v -tf4 -w4; }
args=(render glass.json --method mdom --grid 32 --directions 24)
"$lucent" "${args[@]}" -o mdom-1.pfm 2> /dev/null
for np in 2 3 4; do
  "${mpi[@]}" -np "$np" "$lucent" "${args[@]}" -o "mdom-np$np.pfm" 2> "log-$np" || fail "$np ranks: $(cat "log-$np")"
  grep -q ", $np ranks)" "log-$np" || fail "$np ranks: not shared: $(cat "log-$np")"
  paste <(floats mdom-1.pfm) <(floats "mdom-np$np.pfm") | awk -v what="$np ranks" '
    { n++; a[n] = $1; b[n] = $2; if ($1 > top) top = $1 }
    END {
      if (n != 40 * 36 * 3 || !(top > 0)) { print what ": " n " values, brightest " top; exit 1 }
      for (i = 1; i <= n; i++) { d = a[i] - b[i]; if (d < 0) d = -d; if (d > 1e-6 * top) { print what ": value " i ": " a[i] " against " b[i]; exit 1 } }
    }' || fail "the image differs from one process's"
done

# A grid no rank can hold: exit 1, one line, no image.
if "${mpi[@]}" -np 2 "$lucent" render glass.json --method mdom --grid 1024 -o huge.pfm 2> log-huge; then
  fail "a grid too large succeeded"
fi
[ "$(grep -c 'lucent: error:' log-huge)" = 1 ] || fail "expected one error line, got: $(cat log-huge)"
[ ! -e huge.pfm ] || fail "a failed run wrote its output"

# Rank 1 killed while the ranks sweep: mpirun ends the job, nothing is written.
kill_a_rank killed.pfm 4 "${mpi[@]}" -np 2 "$lucent" render glass.json --method mdom --grid 96 --directions 80 \
  -o killed.pfm
echo "mpi mdom: images within 1e-6 on 1, 2, 3 and 4 ranks; failures end every rank"
