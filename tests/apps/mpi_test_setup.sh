# Sourced by the mpi tests as `source mpi_test_setup.sh LUCENT SOURCE_DIR`:
# sets lucent and source_dir, moves into a scratch directory removed on exit,
# lets OpenMPI run as root (CI's containers) and defines mpi (mpirun, quiet,
# oversubscribed: two cores hold four ranks only so), fail and kill_a_rank.
lucent=$(realpath "$1")
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --quiet --oversubscribe)
fail() { echo "FAIL: $*"; exit 1; }

# kill_a_rank OUTPUT DELAY COMMAND... runs COMMAND (an mpirun of two ranks
# writing OUTPUT) in the background, kills the last of its ranks with SIGKILL
# DELAY seconds after both started, and fails unless mpirun then ends within
# 60 s with a non-zero status and OUTPUT unwritten.
kill_a_rank() {
  local output=$1 delay=$2
  shift 2
  "$@" 2> log-killed &
  local job=$! ranks="" status=0
  # The ranks are mpirun's own children once they run lucent: a match on the
  # command line would also find the ranks of another test run beside this one.
  for _ in $(seq 100); do
    ranks=$(pgrep -P "$job" -x lucent || true)
    [ "$(echo "$ranks" | grep -c .)" -ge 2 ] && break
    sleep 0.1
  done
  local victim
  victim=$(echo "$ranks" | tail -1)
  [ -n "$victim" ] || fail "the ranks never started: $(cat log-killed)"
  sleep "$delay"
  kill -9 "$victim"
  if ! timeout 60 tail --pid="$job" -f /dev/null; then
    pkill -9 -P "$job" || true # a hung job would hold ctest's pipe to its timeout
    kill -9 "$job" || true
    fail "mpirun still runs 60 s after a rank was killed"
  fi
  wait "$job" || status=$?
  [ "$status" != 0 ] || fail "a run with a killed rank exited 0"
  [ ! -e "$output" ] || fail "a run with a killed rank wrote its output"
}
