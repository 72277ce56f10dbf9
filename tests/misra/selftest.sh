#!/bin/sh
# selftest.sh WORK FINDINGS — shows check-misra's judge (judge.py, against
# docs/misra.md) failing where it must, before its verdict on the real
# sources counts (tests/misra.mk):
#   1. a copy of target/ whose tfit_crc32.c has a planted function (a goto,
#      an if without braces, a second return), analysed alone in the
#      portable configuration: the judge must name the goto (Rule 15.1, not
#      recorded), the braces (clang-tidy, not recorded) and the extra return
#      (more Rule 15.5 findings in tfit_crc32.c than recorded);
#   2. FINDINGS (the real ones) with one finding removed: a stale record;
#   3. a .clang-tidy that turns off one more check than the record lists.
set -eu
work=$1 findings=$2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work/planted/target"
cp -R target/src target/include target/.clang-tidy "$work/planted/target/"

crc=$work/planted/target/src/tfit_crc32.c
n=$(wc -l <"$crc")
cat >>"$crc" <<'EOF'

/* Planted by tests/misra/selftest.sh: check-misra must report it. */
uint32_t tfit_planted(uint32_t x);
uint32_t tfit_planted(uint32_t x)
{
    if (x == 0u)
        return 0u;
    if (x > 7u) {
        goto done;
    }
    x = x + 1u;
done:
    return x;
}
EOF
line_if=$((n + 6)) line_goto=$((n + 9))
# tfit_crc32.c alone is enough for these per-file rules and checks.
MISRA_CONFIGS=portable MISRA_SOURCES=target/src/tfit_crc32.c \
    "$here/analyse.sh" "$work/planted" "$work/planted-out"
if "$here/judge.py" check "$work/planted-out/findings.txt" docs/misra.md target/.clang-tidy \
    >"$work/planted.txt"; then
    fail "the judge accepted a copy of target/ with a planted goto, if without braces and second return"
fi
for want in "not in the record: misra-c2012-15.1 target/src/tfit_crc32.c:$line_goto:" \
            "not in the record: readability-braces-around-statements target/src/tfit_crc32.c:$line_if:" \
            "more than the record allows: misra-c2012-15.5 target/src/tfit_crc32.c: "; do
    grep -qF "$want" "$work/planted.txt" || { cat "$work/planted.txt"; fail "the judge did not say: $want"; }
done
echo "planted goto, if without braces and second return in tfit_crc32.c: rejected, each named: ok"

# The record must not claim more than is found.
sed 1d "$findings" >"$work/one-fewer.txt"
removed=$(head -n 1 "$findings")
if "$here/judge.py" check "$work/one-fewer.txt" docs/misra.md target/.clang-tidy >"$work/stale.txt"; then
    fail "the judge accepted a record with one finding more than found ($removed)"
fi
grep -qF "stale record: ${removed%% *} $(echo "${removed#* }" | cut -d: -f1):" "$work/stale.txt" ||
    { cat "$work/stale.txt"; fail "the judge did not name the stale row of ${removed%% *}"; }
echo "a record with one finding more than found: rejected as stale: ok"

# The checks turned off must be the record's.
sed 's/^  -readability-magic-numbers,$/  -readability-magic-numbers,\n  -bugprone-branch-clone,/' \
    target/.clang-tidy >"$work/clang-tidy"
grep -q 'bugprone-branch-clone' "$work/clang-tidy" || fail "could not plant a check in a copy of target/.clang-tidy"
if "$here/judge.py" check "$findings" docs/misra.md "$work/clang-tidy" >"$work/tidy.txt"; then
    fail "the judge accepted a .clang-tidy that turns off an unlisted check"
fi
grep -q "turns off bugprone-branch-clone, which the record" "$work/tidy.txt" || { cat "$work/tidy.txt"; exit 1; }
echo "a .clang-tidy turning off a check the record does not list: rejected: ok"
