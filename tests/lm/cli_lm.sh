#!/bin/sh
# cli_lm.sh TISSUEFIT — the `tissuefit lm-strd` command line: CSV for a good
# file (CRLF as NIST ships it, and LF), the log-response and arctan models,
# exit 2 with file:line for files it cannot use, exit 2 for bad usage.
set -u
tool=$1
# The NIST StRD files live beside the repository; NIST_DIR names another
# place (check-lm shows with it that a missing directory fails).
dir=${NIST_DIR:-../shared/reference/nist-strd}
if [ ! -d "$dir" ]; then
    echo "FAIL: $dir is absent: the NIST StRD files live beside the repository"
    echo "(../shared/reference/nist-strd); without them lm-strd is not tested"
    exit 1
fi
. "$(dirname "$0")/../cli/expect.sh"
# Every lre column of the CSV in $tmp/out is at least 6, and there are N rows.
six_digits() {
    rows=$(awk -F, 'NR > 1' "$tmp/out" | wc -l)
    [ "$rows" = "$2" ] || bad "$1: $rows CSV rows, expected $2"
    awk -F, 'NR > 1 && $4 < 6 { exit 1 }' "$tmp/out" || bad "$1: a value below 6 digits"
}

expect 0 "lm-strd --help" -- "$tool" lm-strd --help
grep -q -- "--start" "$tmp/out" || bad "lm-strd --help lacks --start"
"$tool" --help | grep -q "lm-strd" || bad "tissuefit --help does not list lm-strd"

expect 0 "Misra1a start 1 (CRLF)" -- "$tool" lm-strd "$dir/Misra1a.dat" --start 1
[ "$(head -1 "$tmp/out")" = "name,estimate,certified,lre" ] || bad "CSV header"
grep -q "^rss," "$tmp/out" || bad "no rss row"
grep -q "^b2,0.000550156" "$tmp/out" || bad "Misra1a b2 estimate"
six_digits "Misra1a" 3
grep -q "Misra1a start 1: stop" "$tmp/err" || bad "no progress line on stderr"
cp "$tmp/out" "$tmp/crlf.csv"
expect 1 "Misra1a, standard output on a full disk" -- sh -c '"$0" lm-strd "$1" --start 1 >/dev/full' \
    "$tool" "$dir/Misra1a.dat"
grep -q "cannot write standard output" "$tmp/err" || bad "a full standard output is not reported"
tr -d '\r' <"$dir/Misra1a.dat" >"$tmp/Misra1a-lf.dat"
expect 0 "Misra1a start 1 (LF)" -- "$tool" lm-strd "$tmp/Misra1a-lf.dat" --start 1
cmp -s "$tmp/out" "$tmp/crlf.csv" || bad "LF and CRLF copies give different results"
expect 0 "Nelson start 2 (log y)" -- "$tool" -q lm-strd --start 2 "$dir/Nelson.dat"
six_digits "Nelson" 4
[ -s "$tmp/err" ] && bad "-q still wrote to stderr"
expect 0 "Roszman1 start 1 (arctan)" -- "$tool" lm-strd "$dir/Roszman1.dat" --start=1
six_digits "Roszman1" 5
expect 0 "Thurber start 2, central differences" -- "$tool" lm-strd "$dir/Thurber.dat" --start 2 --central-diff
six_digits "Thurber" 8
expect 0 "BoxBOD start 1 (MINPACK's failure)" -- "$tool" lm-strd "$dir/BoxBOD.dat" --start 1
six_digits "BoxBOD" 3

expect 2 "missing file" -- "$tool" lm-strd "$tmp/none.dat" --start 1
grep -q "$tmp/none.dat: cannot open" "$tmp/err" || bad "missing file not named"
expect 2 "no --start" -- "$tool" lm-strd "$dir/Misra1a.dat"
expect 2 "--start 3" -- "$tool" lm-strd "$dir/Misra1a.dat" --start 3
expect 2 "--start x" -- "$tool" lm-strd "$dir/Misra1a.dat" --start x
expect 2 "two files" -- "$tool" lm-strd "$dir/Misra1a.dat" "$dir/Misra1b.dat" --start 1
expect 2 "unknown option" -- "$tool" lm-strd "$dir/Misra1a.dat" --start 1 --bogus
[ -s "$tmp/out" ] && bad "bad usage printed CSV"

sed '65s/.*/      35.18E0     2x89.0E0\r/' "$dir/Misra1a.dat" >"$tmp/bad-data.dat"
expect 2 "damaged data line" -- "$tool" lm-strd "$tmp/bad-data.dat" --start 1
grep -q "bad-data.dat:65: expected 2 numbers" "$tmp/err" || bad "damaged line not named: $(cat "$tmp/err")"
sed '34s/x\]/x*x]/' "$dir/Misra1a.dat" >"$tmp/bad-model.dat"
expect 2 "unknown model" -- "$tool" lm-strd "$tmp/bad-model.dat" --start 1
grep -q "bad-model.dat:34: unknown model" "$tmp/err" || bad "unknown model not named: $(cat "$tmp/err")"
head -60 "$dir/Misra1a.dat" >"$tmp/short.dat"
expect 2 "truncated file" -- "$tool" lm-strd "$tmp/short.dat" --start 2
grep -q "short.dat:7: bad line range" "$tmp/err" || bad "truncation not named: $(cat "$tmp/err")"
[ -s "$tmp/out" ] && bad "a failed read printed CSV"

finish lm-strd
