#!/bin/sh
# eval.sh TISSUEFIT — `tissuefit eval`: every shipped header's golden
# vectors (float and Q31, every model) as a CSV of inputs give back, through
# eval -i/-o, the golden statuses and outputs bit for bit (9 significant
# digits give back every float, so equal text is equal bits; a changed last
# digit is shown noticed); and the refusals: a missing header, a file that
# is not a generated header, a model not in the header, a Q31 form it does
# not have, a bad cell (file, line, column), a row of the wrong width, a
# compiler that fails — each exits non-zero with its message and writes
# nothing (an existing output is left as it was).
set -u
tool=$1
. "$(dirname "$0")/expect.sh"
export CC="${CC:-cc}"
# eval's build folders go here, so that none left behind can hide
mkdir "$tmp/tt" && export TMPDIR=$tmp/tt

# The models a header declares (without tfit_), float then Q31.
models() { sed -n 's/^extern const tfit_model tfit_\([a-z0-9_]*\);$/\1/p' "$1"; }
models_q31() { sed -n 's/^extern const tfit_model_q31 tfit_\([a-z0-9_]*\);$/\1/p' "$1"; }

# round_trip HEADER MODEL [--q31]: the golden CSV split into inputs and
# expected outputs; eval of the inputs must print the expected text.
round_trip() {
    h=$1 m=$2
    shift 2
    "$tool" -q eval "$h" --model "$m" "$@" --golden -o "$d/g.csv" 2>"$d/err" ||
        { bad "$h $m $*: --golden failed: $(head -3 "$d/err")"; return; }
    k=$(head -1 "$d/g.csv" | tr , '\n' | grep -n '^status$' | cut -d: -f1)
    cut -d, -f1-$((k - 1)) "$d/g.csv" >"$d/in.csv"
    cut -d, -f$k- "$d/g.csv" >"$d/want.csv"
    "$tool" -q eval "$h" --model "$m" "$@" -i "$d/in.csv" -o "$d/got.csv" 2>"$d/err" ||
        { bad "$h $m $*: eval failed: $(head -3 "$d/err")"; return; }
    rows=$(($(wc -l <"$d/want.csv") - 1))
    if cmp -s "$d/want.csv" "$d/got.csv"; then
        echo "ok:   $h $m $*: $rows golden vectors bit for bit"
        sets=$((sets + 1))
        vectors=$((vectors + rows))
    else
        bad "$h $m $*: eval differs from the golden outputs: $(diff "$d/want.csv" "$d/got.csv" | head -3 | cut -c1-160)"
    fi
}

expect 0 "--help lists eval" -- "$tool" --help
prints "--help lists eval" "^  eval "
expect 0 "eval --help" -- "$tool" eval --help
prints "eval --help" "PREFIX/share/tfit/tfit_shim.c"

# region_surface HEADER MODEL: a region surface's golden vectors place its
# proxy directly, so it is run on its law's golden tips instead: the law's
# status and forces must be the law's golden ones, followed by a surface
# status and 3 n_out displacements per row.
region_surface() {
    h=$1 m=$2 law=${2%_surface}_law
    "$tool" -q eval "$h" --model "$law" --golden -o "$d/g.csv" 2>"$d/err" &&
        cut -d, -f1-3 "$d/g.csv" >"$d/in.csv" && cut -d, -f4- "$d/g.csv" >"$d/want.csv" &&
        "$tool" -q eval "$h" --model "$m" -i "$d/in.csv" -o "$d/got.csv" 2>"$d/err" ||
        { bad "$h $m: eval failed: $(head -3 "$d/err")"; return; }
    n_out=$(sed -n "s/^#define TFIT_$(echo "$m" | tr a-z A-Z)_N_OUT \([0-9]*\).*/\1/p" "$h")
    widths=$(awk -F, '{ print NF }' "$d/got.csv" | sort -u)
    if cut -d, -f1-4 "$d/got.csv" | cmp -s - "$d/want.csv" && [ "$widths" = $((5 + 3 * n_out)) ]; then
        echo "ok:   $h $m: its law's $(($(wc -l <"$d/want.csv") - 1)) golden ticks give the law's forces, and $n_out outputs"
        sets=$((sets + 1))
    else
        bad "$h $m: the law's forces differ or the rows are not $((5 + 3 * n_out)) wide ($widths)"
    fi
}

# header_trips HEADER: every model's round trip, in its own folder $d; the
# tally (sets, vectors, failures) in $d/tally.  Two headers at a time.
header_trips() {
    h=$1 d=$tmp/h.$(basename "$1" .h)
    mkdir -p "$d"
    sets=0 vectors=0 fails=0
    for m in $(models "$h"); do
        if grep -q "^#define TFIT_$(echo "$m" | tr a-z A-Z)_FAMILY \"region_surface\"" "$h"; then
            region_surface "$h" "$m"
        else
            round_trip "$h" "$m"
        fi
    done
    for m in $(models_q31 "$h"); do round_trip "$h" "${m%_q31}" --q31; done
    echo "$sets $vectors $fails" >"$d/tally"
}

# EVAL_HEADERS (make check's short version) or every shipped header
headers=${EVAL_HEADERS:-$(ls coeffs/*.h | grep -v '_golden\.h$')}
n=0
for h in $headers; do
    header_trips "$h" >"$tmp/h.$(basename "$h" .h).log" 2>&1 &
    n=$((n + 1))
    [ $((n % 2)) -eq 0 ] && wait
done
wait
sets=0 vectors=0
for h in $headers; do
    name=$(basename "$h" .h)
    cat "$tmp/h.$name.log"
    if read -r s v f <"$tmp/h.$name/tally"; then
        sets=$((sets + s)) vectors=$((vectors + v)) fails=$((fails + f))
    else
        bad "$h: its round trips did not finish"
    fi
done
[ "$sets" -ge 20 ] || bad "only $sets golden sets compared"

# The comparison notices one changed last digit of one output.
d=$tmp/h.block48
sed '2s/\([0-9]\),/\1X,/' "$d/got.csv" | sed '2s/0X,/1,/; 2s/\([1-9]\)X,/0,/' >"$tmp/changed.csv"
cmp -s "$d/want.csv" "$tmp/changed.csv" && bad "a changed digit is not noticed"

# --- refusals: nothing written, an existing output untouched
w=$tmp/w
printf 'fx,fy,fz\n0.1,0.2,-0.3\n' >"$tmp/ok.csv"
expect 2 "eval without -i or --golden" -- "$tool" eval coeffs/block48.h -o "$w/o.csv"
says "eval without -i" "expected NAME.h, -o FILE and one of -i FILE or --golden"
expect 2 "eval, missing header" -- "$tool" eval "$tmp/none.h" -i "$tmp/ok.csv" -o "$w/o.csv"
says "missing header" "none.h: No such file or directory"
expect 2 "eval, not a generated header" -- "$tool" eval target/include/tfit.h -i "$tmp/ok.csv" -o "$w/o.csv"
says "not a generated header" "tfit.h: declares no tfit_model: not a generated header"
expect 2 "eval, model not in the header" -- "$tool" eval coeffs/block48.h --model liver_forward \
    -i "$tmp/ok.csv" -o "$w/o.csv"
says "model not in the header" "no model liver_forward (it has block48_forward, block48_contact"
expect 2 "eval, a Q31 form the header lacks" -- "$tool" eval tests/resonant/block48_dyn.h --q31 \
    -i "$tmp/ok.csv" -o "$w/o.csv"
says "Q31 form" "no Q31 model block48_dyn_forward_q31"
printf 'fx,fy,fz\n0.1,0.2,-0.3\n\n0.1,2x,0\n' >"$tmp/cell.csv"
expect 2 "eval, a bad cell" -- "$tool" eval coeffs/block48.h -i "$tmp/cell.csv" -o "$w/o.csv"
says "a bad cell" "cell.csv:4: column 2: '2x' is not a float32 number"
printf '0.1,0.2,-0.3\n1,2\n' >"$tmp/width.csv"
expect 2 "eval, a short row" -- "$tool" eval coeffs/block48.h -i "$tmp/width.csv" -o "$w/o.csv"
says "a short row" "width.csv:2: 2 columns, expected 3"
expect 2 "eval, a cut model without its progress" -- "$tool" eval coeffs/block48_cut.h \
    -i "$tmp/ok.csv" -o "$w/o.csv"
says "cut model" "ok.csv:2: 3 columns, expected 4"
printf '1e39,0,0\n' >"$tmp/big.csv"
expect 2 "eval, a value beyond float32" -- "$tool" eval coeffs/block48.h -i "$tmp/big.csv" -o "$w/o.csv"
says "beyond float32" "big.csv:1: column 1: '1e39' is not a float32 number"
printf '0.5,0,0\n' >"$tmp/q.csv"
expect 2 "eval --q31, a float where a word goes" -- "$tool" eval coeffs/block48.h --q31 \
    -i "$tmp/q.csv" -o "$w/o.csv"
says "Q31 word" "q.csv:1: column 1: '0.5' is not an int32 word"
expect 1 "eval, a compiler that fails" -- env CC=false "$tool" eval coeffs/block48.h \
    -i "$tmp/ok.csv" -o "$w/o.csv"
says "compiler fails" "block48.h: does not compile with libtfit (CC=false)"
expect 2 "eval into a missing directory" -- "$tool" eval coeffs/block48.h -i "$tmp/ok.csv" \
    -o "$tmp/missing/o.csv"
says "missing directory" "missing/o.csv"
nothing_written "eval refusals"
echo "earlier" >"$w/kept.csv"
expect 2 "eval over an existing output, a bad cell" -- "$tool" eval coeffs/block48.h \
    -i "$tmp/cell.csv" -o "$w/kept.csv"
[ "$(cat "$w/kept.csv")" = earlier ] || bad "a refused eval changed an existing output"
expect 0 "eval, a good run over it" -- "$tool" -q eval coeffs/block48.h -i "$tmp/ok.csv" -o "$w/kept.csv"
[ "$(head -c 24 "$w/kept.csv")" = "status,u0_x,u0_y,u0_z,u1" ] || bad "eval's output lacks its header row"
[ "$(sed -n 2p "$w/kept.csv" | cut -d, -f1)" = 0 ] || bad "an in-envelope force is not status 0"
ls -A "$w" | grep -q tmp && bad "temporary files left behind"
[ -z "$(ls -A "$TMPDIR")" ] || bad "eval's build folders left behind: $(ls -A "$TMPDIR")"

# The compiler eval starts ends with the tool when the terminal sends the
# process group SIGTERM (here: to the tool and the compiler, one kill): it
# inherited the signals blocked from the tool's first thread
# (base/interrupts.h) and kept running without tf_interrupts_child.
# (SIGTERM, because a shell starts a background job with SIGINT ignored.)
printf '#!/bin/sh\necho $$ >"$SLOWCC_PID"\nexec sleep 30\n' >"$tmp/slowcc"
chmod +x "$tmp/slowcc"
SLOWCC_PID="$tmp/slowcc.pid" CC="$tmp/slowcc" "$tool" -q eval coeffs/block48.h \
    -i "$tmp/ok.csv" -o "$w/slow.csv" 2>/dev/null &
i=0
while [ ! -s "$tmp/slowcc.pid" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
ccpid=$(cat "$tmp/slowcc.pid" 2>/dev/null)
if [ -z "$ccpid" ]; then
    bad "eval did not start the compiler"
else
    kill -TERM "$(awk '{ print $4 }' /proc/"$ccpid"/stat)" "$ccpid" # the tool (its parent) and it
    i=0
    while kill -0 "$ccpid" 2>/dev/null && [ $i -lt 30 ]; do sleep 0.1; i=$((i + 1)); done
    if kill -0 "$ccpid" 2>/dev/null; then
        bad "the compiler outlived SIGTERM ($(grep -E "SigBlk|SigIgn" /proc/"$ccpid"/status | tr "\n\t" "  "))"
        kill -KILL "$ccpid"
    fi
fi
wait
runs=$((runs + 1))

echo "eval: $sets golden sets, $vectors vectors, through -i/-o bit for bit"
finish eval
