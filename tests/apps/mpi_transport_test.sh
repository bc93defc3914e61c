#!/usr/bin/env bash
# lucent transport under mpirun with real ranks (docs/mpi.md): the sweeps
# shared KBA-style give the flux of one process within 1e-6 relative on 1, 2, 3
# and 4 ranks (process grids 1x1, 1x2, 1x3 and 2x2), with the uncollided flux
# marched and swept; a problem no rank can read exits 1 with one error line and
# no output, and so does a problem with fewer columns of cells than ranks; a
# rank killed mid-sweep ends the run with no output, never a hang.
#   mpi_transport_test.sh LUCENT SOURCE_DIR
set -euo pipefail
source "$(dirname "$(realpath "$0")")/mpi_test_setup.sh" "$@"

# Kobayashi's problem 1 with 50% scattering (three reflective faces) on a
# coarser grid: marched, and swept with two bands and anisotropic scattering.
k1=$source_dir/models/transport/kobayashi-1-scatter.json
sed -e 's/"cells": \[50, 50, 50\]/"cells": [16, 16, 16]/' -e 's/"directions": 120/"directions": 48/' "$k1" > marched.json
sed -e 's/"marched"/"swept"/' -e 's/"bands": 1/"bands": 2/' -e 's/"sigma_s": 0.05}/"sigma_s": 0.05, "g": 0.5}/' \
  marched.json > swept.json
for problem in marched swept; do
  "$lucent" transport "$problem.json" -o "$problem-1.csv" 2> /dev/null
  for np in 1 2 3 4; do
    "${mpi[@]}" -np "$np" "$lucent" transport "$problem.json" -o "$problem-np$np.csv" 2> "log-$problem-$np" ||
      fail "$problem on $np ranks: $(cat "log-$problem-$np")"
    [ "$np" = 1 ] || grep -q "$np ranks trading" "log-$problem-$np" || fail "$problem on $np ranks: not shared"
    # Every point's flux within 1e-6 relative of one process's (no point missing).
    paste -d, "$problem-1.csv" "$problem-np$np.csv" | tail -n +2 | awk -F, -v what="$problem on $np ranks" '
      { n++; d = $8 - $4; if (d < 0) d = -d; if (!($4 > 0) || d > 1e-6 * $4) { print what ": " $0; bad = 1 } }
      END { if (n != 30) { print what ": " n " points, not 30"; bad = 1 } exit bad }' || fail "flux differs"
  done
done

# A problem every rank fails to read: exit 1, one line, no output.
if "${mpi[@]}" -np 3 "$lucent" transport missing.json -o missing.csv 2> log-missing; then
  fail "a missing problem succeeded"
fi
[ "$(grep -c 'lucent: error:' log-missing)" = 1 ] || fail "expected one error line, got: $(cat log-missing)"
[ ! -e missing.csv ] || fail "a failed run wrote its output"

# More ranks than columns of cells: refused before the sweeps, one line.
cat > thin.json << 'JSON'
{"domain": {"min": [0, 0, 0], "max": [1, 1, 4], "cells": [1, 1, 4]},
 "regions": [{"min": [0, 0, 0], "max": [1, 1, 4], "sigma_t": 1, "sigma_s": 0.5, "source": 1}],
 "points": [[0.5, 0.5, 2]], "solver": {"directions": 8}}
JSON
if "${mpi[@]}" -np 2 "$lucent" transport thin.json -o thin.csv 2> log-thin; then fail "2 ranks on 1 column succeeded"; fi
[ "$(grep -c 'lucent: error:.*columns of cells' log-thin)" = 1 ] || fail "expected one error line, got: $(cat log-thin)"
[ ! -e thin.csv ] || fail "a refused run wrote its output"

# Rank 1 killed while the ranks sweep (the uncollided flux swept: sweeps from
# the start): mpirun ends the job, rank 0 waiting for its faces writes nothing.
sed -e 's/"cells": \[50, 50, 50\]/"cells": [40, 40, 40]/' -e 's/"marched"/"swept"/' "$k1" > long.json
kill_a_rank killed.csv 2 "${mpi[@]}" -np 2 "$lucent" transport long.json -o killed.csv
echo "mpi transport: flux within 1e-6 on 1-4 ranks; failures end every rank"
