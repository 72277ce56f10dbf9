#!/bin/sh
# run_tests.sh JOBS LOGDIR PROGRAM... — run test programs JOBS at a time
# (make check's host unit tests: one core each, so a 2-core machine runs
# two), each one's output to LOGDIR/NAME.log.  The logs are then printed in
# the order given, so the output reads as a serial run's would, followed by
# the three slowest programs; exit 1 naming every program that failed.
#
# Programs run in parallel must not share files: the unit tests write only
# under mkdtemp(3) directories.  OpenMP threads wait passively, or two
# programs that each spin two threads on two cores starve each other.
set -eu
jobs=$1 logs=$2
shift 2
mkdir -p "$logs"
export OMP_WAIT_POLICY=passive
# One log name per program: a path's folders joined by '-'.
name() { echo "$1" | sed 's|.*/tests/||; s|/|-|g'; }

rm -f "$logs"/*.status
# xargs hands each program to its own shell: $0 is LOGDIR, $1 the program.
for p in "$@"; do echo "$p"; done | xargs -P "$jobs" -n 1 sh -c '
  n=$(echo "$1" | sed "s|.*/tests/||; s|/|-|g")
  s=$(date +%s%N)
  if "$1" >"$0/$n.log" 2>&1; then rc=0; else rc=$?; fi
  echo "$rc $(( ($(date +%s%N) - s) / 1000000 ))" >"$0/$n.status"' "$logs"

failed=""
for p in "$@"; do
  n=$(name "$p")
  cat "$logs/$n.log"
  if [ ! -f "$logs/$n.status" ]; then failed="$failed $p(did-not-run)"; continue; fi
  read -r rc _ <"$logs/$n.status"
  [ "$rc" = 0 ] || failed="$failed $p(exit-$rc)"
done
slowest=$(for p in "$@"; do n=$(name "$p"); [ -f "$logs/$n.status" ] &&
  echo "$(cut -d' ' -f2 "$logs/$n.status") $n"; done |
  sort -rn | head -3 | awk '{printf "%s%s %.1f s", (NR > 1 ? ", " : ""), $2, $1 / 1000}')
echo "slowest: $slowest"
if [ -n "$failed" ]; then
  echo "FAILED:$failed"
  exit 1
fi
