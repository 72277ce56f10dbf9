#!/bin/sh
# run_checks.sh LANES DIR NAME CHECK... — make check's checks, LANES at a
# time: each check is its own make ($MAKE $MAKE_JOBS CHECK), its output in
# DIR/CHECK.log, guarded by tests/check_guard.sh (a heading first, a result
# line last).  A line is printed as each check ends; then every log in the
# order given, so that the output reads as a serial run's would; then the
# slowest checks.  DIR/NAME.seconds gets "WALL CHECK CPU" per check (CPU:
# user + system of everything the check ran, from the shell's `times`).
# Exit 1 naming every check that failed.
#
# Checks run side by side must not build the same file: make check builds
# every file they depend on first (tests/check_files.awk), and what a
# check's recipe writes is its own (its build/ folder, mkdtemp(3)).
set -eu
lanes=$1 dir=$2 name=$3
shift 3
mkdir -p "$dir"
for c in "$@"; do rm -f "$dir/$c.status" "$dir/$c.log"; done
start=$(date +%s)
# xargs hands each check to its own shell: $0 is DIR, $1 the check.
for c in "$@"; do echo "$c"; done | xargs -P "$lanes" -n 1 sh -c '
  dir=$0 c=$1
  s=$(date +%s)
  if ${MAKE:-make} --no-print-directory ${MAKE_JOBS:-} "$c" >"$dir/$c.log" 2>&1 </dev/null &&
     tests/check_guard.sh "$c" "$dir/$c.log" >"$dir/$c.guard"; then rc=0; else rc=1; fi
  times >"$dir/$c.times"   # in this shell: a subshell would count no children
  cpu=$(awk -f tests/times_cpu.awk "$dir/$c.times")
  w=$(( $(date +%s) - s ))
  echo "$rc $w $cpu" >"$dir/$c.status"
  printf "%-6s %-28s %4d s (%d s of CPU)\n" "$([ $rc = 0 ] && echo done || echo FAILED)" "$c" "$w" "$cpu"' "$dir"
elapsed=$(( $(date +%s) - start ))

failed="" secs="$dir/$name.seconds"
: >"$secs"
for c in "$@"; do
    echo
    cat "$dir/$c.log"
    [ -s "$dir/$c.guard" ] && cat "$dir/$c.guard"
    if [ ! -f "$dir/$c.status" ]; then
        failed="$failed $c(did-not-run)"
        continue
    fi
    read -r rc w cpu <"$dir/$c.status"
    echo "$w $c $cpu" >>"$secs"
    [ "$rc" = 0 ] || failed="$failed $c"
done
echo
sort -rn "$secs" | awk -v e="$elapsed" -v l="$lanes" '{ t += $1; c += $3;
  if (NR <= 8) top = top (NR > 1 ? ", " : "") $2 " " $1 " s" }
  END { printf "slowest checks: %s; all %d s, %d at a time: %d s elapsed (%d s of CPU: user + system)\n",
        top, t, l, e, c }'
if [ -n "$failed" ]; then
    echo "FAILED:$failed"
    exit 1
fi
