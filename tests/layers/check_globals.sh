#!/bin/sh
# check_globals.sh OBJECT... — no mutable state in the given objects: no
# data or thread-local symbol in a writable section (.data, .bss, their .rel
# and thread-local variants, common symbols).  A const table stays in
# .rodata or, when it holds pointers, in .data.rel.ro (written once by the
# loader, then read-only), so it passes; nm cannot tell .data.rel.ro from
# .data (both "d"), hence objdump.  Allowed: OpenMP's named-critical locks
# (.gomp_critical_user_*), which belong to the runtime.
# Prints each offending symbol and the verdict; exits 1 on any.
set -u
n=0 bad=0
for o in "$@"; do
    n=$((n + 1))
    objdump -t "$o" | awk -v o="$o" '
        # VALUE FLAGS(7 characters) SECTION<TAB>SIZE NAME
        match($0, /^[0-9a-f]+ /) {
            flags = substr($0, RLENGTH + 1, 7)
            rest = substr($0, RLENGTH + 9)
            sec = rest; sub(/\t.*/, "", sec)
            sym = $NF
            if (flags ~ /[dfF]/) next           # section, file and function symbols
            if (sec !~ /^(\.data|\.bss|\.tdata|\.tbss|\*COM\*)/) next
            if (sec ~ /^\.data\.rel\.ro/) next
            if (sym ~ /^\.gomp_critical_user_/) next
            printf "%s: %s in %s: mutable state\n", o, sym, sec
            bad = 1
        }
        END { exit bad }' || bad=1
done
if [ "$bad" != 0 ]; then
    echo "FAIL: mutable global or static state in $n object(s) checked"
    exit 1
fi
echo "ok: no mutable global or static state in $n objects"
