#!/usr/bin/env bash
# lucent render under mpirun with real ranks (docs/mpi.md), on the bundled
# sphere: the path tracer's and the reference's images are byte-identical for
# 1, 2 and 4 ranks; a failure on every rank is one error line and no output; a
# rank killed outright ends the run with no output, never a hang.
#   mpi_render_test.sh LUCENT SOURCE_DIR
set -euo pipefail
source "$(dirname "$(realpath "$0")")/mpi_test_setup.sh" "$@"
cp "$source_dir/models/sphere.json" "$source_dir/models/sphere.obj" .

for method in path reference; do
  args=(render sphere.json --method "$method" --width 40 --height 36 --seed 3)
  [ "$method" = path ] && args+=(--samples 8)
  "$lucent" "${args[@]}" -o "$method-1.pfm" 2> /dev/null
  for np in 1 2 4; do
    "${mpi[@]}" -np "$np" "$lucent" "${args[@]}" -o "$method-np$np.pfm" 2> "log-$method-$np" ||
      fail "$method on $np ranks: $(cat "log-$method-$np")"
    cmp -s "$method-1.pfm" "$method-np$np.pfm" || fail "$method on $np ranks differs from one process"
  done
done

# A scene every rank fails to read: exit 1, one line, no image.
if "${mpi[@]}" -np 3 "$lucent" render missing.json -o missing.pfm 2> log-missing; then fail "a missing scene succeeded"; fi
[ "$(grep -c 'lucent: error:' log-missing)" = 1 ] || fail "expected one error line, got: $(cat log-missing)"
[ ! -e missing.pfm ] || fail "a failed run wrote its output"

# Rank 1 killed while the ranks trace: mpirun ends the job, nothing is written.
kill_a_rank killed.pfm 0.5 "${mpi[@]}" -np 2 "$lucent" render sphere.json --method path --samples 100000 \
  --width 64 --height 64 -o killed.pfm
echo "mpi render: images identical on 1, 2 and 4 ranks; failures end every rank"
