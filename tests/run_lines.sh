#!/bin/sh
# run_lines.sh JOBS LOGDIR — runs every line of standard input as a shell
# command, JOBS at a time (make check's serial loops of independent
# single-core runs: QEMU golden runs, held-out checks), each one's output to
# LOGDIR/N.out; then prints the outputs in the order given, so that the log
# reads as a serial run's would, and exits 1 naming every command that
# failed.  Commands run at once must not write the same files.
set -eu
jobs=$1 logs=$2
mkdir -p "$logs"
rm -f "$logs"/*.out "$logs"/*.status "$logs/lines"
# Numbered so that the outputs can be printed in their order.
awk 'NF { print NR "\t" $0 }' >"$logs/lines"
cut -f1 "$logs/lines" | xargs -P "$jobs" -n 1 sh -c '
  cmd=$(awk -F "\t" -v n="$1" "\$1 == n { sub(/^[^\t]*\t/, \"\"); print; exit }" "$0/lines")
  if sh -c "$cmd" >"$0/$1.out" 2>&1; then echo 0; else echo $?; fi >"$0/$1.status"' "$logs"
failed=""
while IFS="$(printf '\t')" read -r i cmd; do
    cat "$logs/$i.out"
    [ "$(cat "$logs/$i.status" 2>/dev/null)" = 0 ] || failed="$failed
  $cmd"
done <"$logs/lines"
if [ -n "$failed" ]; then
    echo "FAILED:$failed"
    exit 1
fi
