#!/usr/bin/env bash
# Times CI as CI runs it: a fresh clone of this checkout's HEAD in a new folder,
# then .ci/run's two steps (the test command of README.md, then the sanitizer
# suite), each timed, with the tests each one ran. The system packages are not
# removed first: a machine where scripts/install-deps.sh must install them all
# adds their download and install to the first step.
#   scripts/time-ci.sh [--record docs/results/ci.md] [--keep]
set -euo pipefail
cd "$(dirname "$0")/.."
record="" keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --record) record="${2:?--record needs a file}"; shift 2 ;;
    --keep) keep=1; shift ;;
    *) echo "time-ci.sh: unknown option '$1' (known: --record FILE, --keep)" >&2; exit 2 ;;
  esac
done
if [ -n "$record" ]; then
  : > "$record.tmp" || { echo "time-ci.sh: error: $record: cannot write" >&2; exit 1; }
  rm -f "$record.tmp"
fi
commit=$(git rev-parse --short=12 HEAD)
git diff --quiet HEAD -- || commit="$commit + uncommitted changes (not in the clone)"
work=$(mktemp -d /tmp/lucent-ci-XXXXXX)
[ "$keep" -eq 1 ] || trap 'rm -rf "$work"' EXIT
git clone -q "$(pwd)" "$work/lucent"

step() {  # step NAME COMMAND...: runs it in the clone, logs it, prints seconds and tests
  local name=$1 start end log="$work/$1.log"; shift
  start=$(date +%s)
  if ! (cd "$work/lucent" && CI=true "$@") > "$log" 2>&1 < /dev/null; then
    echo "time-ci.sh: error: $name failed; its output: $log" >&2
    trap - EXIT
    exit 1
  fi
  end=$(date +%s)
  local tests
  tests=$(grep -E 'tests passed, [0-9]+ tests failed out of [0-9]+' "$log" |
          awk '{n += $NF} END {print n + 0}')
  echo "$name $((end - start)) ${tests:-0}"
}

echo "time-ci.sh: $work/lucent at $commit" >&2
read -r _ test_s test_n < <(step test scripts/test.sh)
echo "time-ci.sh: test step $test_s s, $test_n tests" >&2
read -r _ san_s san_n < <(step sanitize scripts/sanitize.sh)
echo "time-ci.sh: sanitizer step $san_s s, $san_n tests" >&2
total=$((test_s + san_s))

model=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
mem=$(awk '/MemTotal/ {printf "%.1f", $2 / 1048576}' /proc/meminfo)
text="# time-ci.sh

- command: \`time-ci.sh${record:+ --record $record}\`
- commit: $commit
- machine: $model, $(nproc) cores, $mem GiB; system packages already installed
- date: $(date -u '+%Y-%m-%d %H:%M UTC')

\`.ci/run\` on a fresh clone: the build from nothing and every test, then the
sanitizer build and every test but the accuracy tier under ASan and UBSan
(scripts/sanitize.sh). CI's limit is 90 minutes; the project's goal is under 60.

| step | what it runs | time (min) | tests |
|---|---|---:|---:|
| 1 | \`scripts/test.sh\` (README's test command) | $(awk "BEGIN {printf \"%.1f\", $test_s / 60}") | $test_n |
| 2 | \`scripts/sanitize.sh\` | $(awk "BEGIN {printf \"%.1f\", $san_s / 60}") | $san_n |
| all | \`.ci/run\` | $(awk "BEGIN {printf \"%.1f\", $total / 60}") | $((test_n + san_n)) |
"
echo "$text"
if [ -n "$record" ]; then
  printf '%s' "$text" > "$record.tmp" && mv "$record.tmp" "$record"
  echo "time-ci.sh: recorded in $record" >&2
fi
