# check_files.awk — the files a list of phony targets needs, from make's
# database (`make -pq` on standard input): ROOTS (awk -v) names the phony
# targets; every prerequisite that is not phony is printed once, and the
# prerequisites of phony ones are followed in turn.  Order-only
# prerequisites (after "|") are left out: they are the deps-* installers.
# `make check` builds the printed files with one make before it runs the
# checks side by side (tests/run_checks.sh), so that no two checks' makes
# build the same file at once.
/^\.PHONY:/ {
    for (i = 2; i <= NF; i++)
        phony[$i] = 1
    next
}
# a rule line: "target: prerequisites | order-only"; not a variable
# (make prints those with "=" or ":="), not a recipe (tab), not a comment
/^[^#\t][^=]*:/ && !/=/ {
    t = $0
    sub(/:.*/, "", t)
    if (t ~ /[ %]/)
        next
    p = $0
    sub(/^[^:]*:+/, "", p)
    sub(/\|.*/, "", p)
    deps[t] = deps[t] " " p
}
END {
    n = split(ROOTS, queue, " ")
    for (head = 1; head <= n; head++) {
        t = queue[head]
        if (seen[t]++)
            continue
        m = split(deps[t], d, " ")
        for (i = 1; i <= m; i++) {
            if (d[i] in phony)
                queue[++n] = d[i]
            else if (!printed[d[i]]++)
                print d[i]
        }
    }
}
