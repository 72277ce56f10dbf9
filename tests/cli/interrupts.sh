#!/bin/sh
# interrupts.sh TOOL N — N signals at random moments of `tissuefit fit` over
# an existing header and golden pair (`make check-interrupts`; check-outputs
# sends them at chosen points of the writes, deterministically).  The
# signals are SIGINT, SIGTERM and SIGKILL, sent from outside to the process
# (the kernel hands a process-directed signal to any
# thread that does not block it: the tool's OpenMP workers exist while it
# writes), at moments drawn over the last 70 % of a fit, where the files are
# written.  After each:
#   - SIGINT and SIGTERM leave no temporary file (*.tmp.*);
#   - the pair is never a header and a golden file from different runs
#     unless the golden file's #error says so (compiled as a firmware would);
#   - SIGKILL may leave temporaries (nothing can hold it): they are removed.
# Prints the tally; exits 1 on any failure.
set -u
tool=$1 n=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/expect.sh"
scene=tests/solver/block48_seed.yaml
d=$tmp/pair
mkdir -p "$d"
"$tool" -q fit "$scene" -o "$d/pair.h" || { echo "FAIL: the first fit"; exit 1; }

# The fit's duration, ms (the moments are drawn around its end).
s=$(date +%s%N)
"$tool" -q fit "$scene" -o "$tmp/timed.h"
ms=$(( ($(date +%s%N) - s) / 1000000 ))

pair_matches() {
    printf '#include "pair_golden.h"\nint main(void) { return 0; }\n' |
        cc -std=c11 -fsyntax-only -Itarget/include -I"$d" -x c - 2>"$tmp/cc"
}

sent_int=0 sent_term=0 sent_kill=0 ended=0
i=0
while [ "$i" -lt "$n" ]; do
    i=$((i + 1))
    r=$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')
    case $((r % 3)) in
    0) sig=INT; sent_int=$((sent_int + 1)) ;;
    1) sig=TERM; sent_term=$((sent_term + 1)) ;;
    *) sig=KILL; sent_kill=$((sent_kill + 1)) ;;
    esac
    # a moment in [0.3 ms, ms]
    at=$(( ms * 3 / 10 + (r / 3) % (ms * 7 / 10 + 1) ))
    "$tool" -q fit "$scene" -o "$d/pair.h" 2>/dev/null &
    p=$!
    sleep "$(printf '%d.%03d' $((at / 1000)) $((at % 1000)))"
    kill -s "$sig" "$p" 2>/dev/null || ended=$((ended + 1))
    wait "$p" 2>/dev/null
    left=$(ls "$d" | grep -c '\.tmp\.' || true)
    if [ "$left" -gt 0 ]; then
        if [ "$sig" = KILL ]; then
            rm -f "$d"/*.tmp.*
        else
            bad "SIG$sig at $at ms of $ms: $left temporary file(s) left: $(ls "$d" | tr '\n' ' ')"
            rm -f "$d"/*.tmp.*
        fi
    fi
    # a mixed pair must say so (its golden file's #error); only SIGKILL,
    # between the two renames, can make one
    if ! pair_matches; then
        if ! grep -q '#error' "$tmp/cc"; then
            bad "SIG$sig at $at ms: the pair does not compile: $(head -3 "$tmp/cc")"
        elif [ "$sig" != KILL ]; then
            bad "SIG$sig at $at ms: a header and golden file from different runs"
        fi
        "$tool" -q fit "$scene" -o "$d/pair.h" # the next try starts from a pair
    fi
done
runs=$n
[ "$fails" -eq 0 ] && echo "interrupts: $n signals (SIGINT $sent_int, SIGTERM $sent_term, SIGKILL $sent_kill) over a ${ms} ms fit, $ended after it ended"
finish "interrupts: $n signals at random moments of fit: no temporary left by SIGINT or SIGTERM, the pair never mixed without its #error"
