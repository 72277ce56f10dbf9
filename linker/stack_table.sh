#!/bin/sh
# stack_table.sh CALLGRAPH "FUNCTIONS" CORE:IMAGE.elf:OBJDIR...
# Worst-case stack (bytes) of each listed function: its own frame from the
# compiler's -fstack-usage files (OBJDIR/*.su) plus the deepest path through
# the functions it calls, taken from the linked library's disassembly by the
# call-graph checker (tests/freestanding/callgraph.c, which also proves there
# is no recursion, so every path is finite).  A tail call is counted as a
# call, so the figures are upper bounds.  Fails if a frame is dynamic
# (alloca, variable-length array) or a called function has no frame record.
set -eu
callgraph=$1 functions=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
header="function"
for spec in "$@"; do header="$header $(echo "$spec" | cut -d: -f1)"; done
for spec in "$@"; do
    core=$(echo "$spec" | cut -d: -f1)
    elf=$(echo "$spec" | cut -d: -f2)
    objdir=$(echo "$spec" | cut -d: -f3)
    # No pipes: /bin/sh has no pipefail, and a checker that fails (recursion
    # found, unreadable image) must stop the table, not feed it nothing.
    arm-none-eabi-objdump -d "$elf" >"$tmp/$core.dis"
    "$callgraph" <"$tmp/$core.dis" >"$tmp/$core.graph"
    awk '$2 == "->" { print $1, $3 }' "$tmp/$core.graph" >"$tmp/$core.edges"
    awk -F'\t' '{ n = split($1, p, ":"); print p[n], $2, $3 }' "$objdir"/*.su >"$tmp/$core.frames"
    if grep -q dynamic "$tmp/$core.frames"; then
        echo "stack_table: dynamic stack frame in the $core library:"; grep dynamic "$tmp/$core.frames"
        exit 1
    fi
    for f in $functions; do
        awk -v root="$f" -v core="$core" '
            FILENAME ~ /frames$/ { frame[$1] = $2; next }
            { callees[$1] = callees[$1] " " $2 }
            function worst(fn,    n, list, i, w, best) {
                if (fn in memo) return memo[fn]
                if (!(fn in frame)) { printf "stack_table: %s: no frame for %s\n", core, fn > "/dev/stderr"; exit 1 }
                best = 0
                n = split(callees[fn], list, " ")
                for (i = 1; i <= n; i++) { w = worst(list[i]); if (w > best) best = w }
                return memo[fn] = frame[fn] + best
            }
            END { print root, worst(root) }' "$tmp/$core.frames" "$tmp/$core.edges" >>"$tmp/$core.table"
    done
done
echo "$header" | awk '{ printf "%-24s", $1; for (i = 2; i <= NF; i++) printf " %8s", $i; print "" }'
for f in $functions; do
    printf '%-24s' "$f"
    for spec in "$@"; do
        core=$(echo "$spec" | cut -d: -f1)
        printf ' %8s' "$(awk -v f="$f" '$1 == f { print $2 }' "$tmp/$core.table")"
    done
    echo
done
