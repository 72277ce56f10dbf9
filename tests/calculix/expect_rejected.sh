# expect_rejected.sh — sourced by the data checks' scripts (check_data.sh,
# check_nlgeom.sh): expect_rejected NAME runs `check "$tmp"` on a broken copy
# of the data in $tmp and counts it in $fails unless the checker rejects it
# (exit 1), printing the checker's first FAIL line as the reason.
expect_rejected() {
    check "$tmp" > "$tmp/out" 2>&1
    st=$?
    if [ "$st" = 1 ]; then
        echo "ok:   rejects $1 ($(grep -m1 FAIL "$tmp/out"))"
    else
        echo "FAIL: accepted $1 (exit $st)"; fails=$((fails + 1))
    fi
}
