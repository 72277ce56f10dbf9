#!/bin/sh
# run.sh BENCH_BINARY HEADER.h [CALLS] — one table per header: native ns per
# evaluation (median, p99, max over CALLS calls, default 100000, pinned to
# one core with taskset when it exists), instructions per call (callgrind),
# the speed-up over the seed's 0.1509 s per evaluation (Zhou et al. 2017),
# and the header's own firmware figures: Arm instructions per call (checked
# against QEMU by make check-cycles) and the estimated microseconds on a
# Cortex-M4F at 168 MHz and a Cortex-M7 at 480 MHz (host/cost/cycles.c);
# then the coefficients of the model (float: n_coef; Q31: table words) and
# the M4F upper-bound cycles per coefficient (TFIT_NAME_CYCLES_M4F / n_coef).
set -eu
bin=$1 header=$2 calls=${3:-100000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pin=""
if command -v taskset >/dev/null 2>&1 && taskset -c 1 true 2>/dev/null; then pin="taskset -c 1"; fi
$pin "$bin" time "$calls" >"$tmp/time"
valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" --toggle-collect='tfit_displacements*' \
    --toggle-collect='tfit_contact_force*' "$bin" count 1000 >/dev/null 2>&1
for f in "$tmp"/cg.out.*; do
    awk '/^desc: Trigger: Client Request:/ { sub(/.*Request: /, ""); label = $0 }
         /^(totals|summary):/ { total = $2 }
         END { print label, total }' "$f"
done >"$tmp/count"
# model names in set order: float models, then those with a Q31 form
sed -n 's/^extern const tfit_model tfit_\([a-z0-9_]*\);$/float \1/p' "$header" | awk '{ print $1, NR - 1, $2 }' >"$tmp/names"
sed -n 's/^extern const tfit_model_q31 tfit_\([a-z0-9_]*\)_q31;$/q31 \1/p' "$header" | awk '{ print $1, NR - 1, $2 }' >>"$tmp/names"
echo "== $(basename "$header"): native, $calls calls per model${pin:+ (taskset -c 1)} =="
printf '%-22s %-5s %5s %9s %9s %9s %10s %9s %10s %8s %7s %6s %9s\n' model kind n_out "median" "p99" "max" \
    "insns/call" "x seed" "ARM insns" "M4F us" "M7 us" "coefs" "M4F c/coef"
awk -v header="$header" '
    FILENAME ~ /names$/ { name[$1 " " $2] = $3; next }
    FILENAME ~ /count$/ { insns[$1 " " $2] = $3; next }
    {
        key = $1 " " $2; n = name[key]
        up = toupper(n)
        m4 = "-"; m7 = "-"; arm = "-"; cyc = ""; per = "-"
        if ($1 == "float") {
            cmd = "sed -n \"s/^#define TFIT_" up "_CYCLES_M4F \\([0-9]*\\)u.*/\\1/p\" " header
            cmd | getline cyc; close(cmd)
            if (cyc != "" && $7 > 0) per = sprintf("%.3f", cyc / $7)
            cmd = "sed -n \"s/^#define TFIT_" up "_INSNS_ARMV7EM \\([0-9]*\\).*/\\1/p\" " header
            cmd | getline arm; close(cmd)
            cmd = "sed -n \"s/^#define TFIT_" up "_US_M4F_168MHZ \\([0-9.]*\\).*/\\1/p\" " header
            cmd | getline m4; close(cmd)
            cmd = "sed -n \"s/^#define TFIT_" up "_US_M7_480MHZ \\([0-9.]*\\).*/\\1/p\" " header
            cmd | getline m7; close(cmd)
        }
        printf "%-22s %-5s %5d %6.0f ns %6.0f ns %6.0f ns %10.0f %9.3g %10s %8s %7s %6d %9s\n", n, $1, $3,
               $4, $5, $6, insns[key] / 1000, 0.1509e9 / $4, arm, m4, m7, $7, per
    }' "$tmp/names" "$tmp/count" "$tmp/time"
