#!/bin/sh
# check_includes.sh DIR "LAYER..." — the include structure of host/ (DIR):
#   - DIR holds folders only, besides its make fragment host.mk;
#   - every folder is a layer of the list, which runs from the lowest to the
#     highest (host.mk's HOST_LAYERS); a subfolder belongs to its top folder;
#   - every #include "..." names a file from DIR ("solvers/solver.h") or
#     target/include ("tfit.h"), and no file includes a higher layer;
#   - the include graph between files has no cycle (tsort finds it), nor
#     the graph between modules, a .c and its .h taken as one (x.c including
#     y.h while y.c includes x.h is a cycle of modules though no file loops).
# Prints one line per violation and the verdict; exits 1 on any violation.
set -u
dir=$1 layers=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0

for f in "$dir"/* "$dir"/.[!.]*; do
    [ -e "$f" ] || continue
    name=$(basename "$f")
    if [ -d "$f" ]; then
        case " $layers " in
        *" $name "*) ;;
        *) echo "host/$name/: a folder that is not in the layer list (host.mk HOST_LAYERS)"; bad=1 ;;
        esac
    elif [ "$name" != host.mk ]; then
        echo "host/$name: only host.mk may sit in host/ itself; files go into a layer's folder"
        bad=1
    fi
done

# FILE<TAB>LINE<TAB>INCLUDED for every quoted include
find "$dir" -name '*.[ch]' | LC_ALL=C sort | while read -r f; do
    awk -v f="${f#"$dir"/}" '
        /^[ \t]*#[ \t]*include[ \t]*"/ {
            s = $0; sub(/^[^"]*"/, "", s); sub(/".*$/, "", s)
            print f "\t" FNR "\t" s
        }' "$f"
done >"$tmp/includes"

awk -F'\t' -v layers="$layers" -v dir="$dir" -v graph="$tmp/graph" '
    BEGIN {
        n = split(layers, name, " ")
        for (i = 1; i <= n; ++i) rank[name[i]] = i
    }
    function exists(path,    line) {
        if ((getline line < path) >= 0) { close(path); return 1 }
        return 0
    }
    {
        file = $1; line = $2; inc = $3
        from = file; sub(/\/.*/, "", from)
        if (exists(dir "/" inc)) {
            to = inc; sub(/\/.*/, "", to)
            if (index(inc, "/") == 0 || !(to in rank)) {
                printf "host/%s:%s: includes \"%s\", which is not in a layer folder\n", file, line, inc
                bad = 1
            } else if (rank[to] > rank[from]) {
                printf "host/%s:%s: upward include of \"%s\": layer %s is above %s\n", file, line,
                       inc, to, from
                bad = 1
            }
            print inc, file > graph
        } else if (!exists("target/include/" inc)) {
            printf "host/%s:%s: \"%s\" is neither a host/ path nor a target/include header\n",
                   file, line, inc
            bad = 1
        }
    }
    END { exit bad }' "$tmp/includes" || bad=1

if [ -s "$tmp/graph" ] && ! tsort "$tmp/graph" >/dev/null 2>"$tmp/tsort"; then
    echo "include cycle between files:"
    sed -n 's/^tsort: /  /p' "$tmp/tsort" | grep -v "input contains a loop"
    bad=1
fi

# the same graph between modules: x.c and x.h are one node
if [ -s "$tmp/graph" ]; then
    awk '{ a = $1; b = $2; sub(/\.[ch]$/, "", a); sub(/\.[ch]$/, "", b); if (a != b) print a, b }' \
        "$tmp/graph" >"$tmp/modules"
    if [ -s "$tmp/modules" ] && ! tsort "$tmp/modules" >/dev/null 2>"$tmp/tsort"; then
        echo "include cycle between modules (a .c and its .h as one):"
        sed -n 's/^tsort: /  /p' "$tmp/tsort" | grep -v "input contains a loop"
        bad=1
    fi
fi

files=$(find "$dir" -name '*.[ch]' | wc -l)
edges=$(wc -l <"$tmp/includes")
if [ "$bad" != 0 ]; then
    echo "FAIL: host/ include structure ($files files, $edges includes)"
    exit 1
fi
echo "ok: host/ include structure: $files files, $edges includes, $(echo $layers | wc -w) layers, no upward include, no cycle between files or modules"
