#!/bin/sh
# analyse.sh ROOT OUT — the static analysis of libtfit (check-misra,
# docs/misra.md): cppcheck with its MISRA C:2012 addon, and clang-tidy with
# target/.clang-tidy, over ROOT/target/src/*.c and the headers they include
# (target/src/*.h, target/include/*.h).  Writes OUT/findings.txt, one line
# per finding, sorted and unique:
#     ID FILE:LINE:COLUMN
# ID is misra-c2012-R.N, a cppcheck check (e.g. ctuuninitvar) or a
# clang-tidy check; FILE is relative to ROOT.  Exits non-zero if a tool
# fails or a source is not analysed.
#
# Each tool sees the sources in two configurations, the two paths the
# library compiles to (target/src/tfit_internal.h): "portable" (the C
# evaluator: x86-64, RV64, -DTFIT_PORTABLE) and "armv7em" (Cortex-M4F/M7 at
# -O2: the inline assembly of *_armv7em.c).  cppcheck has no system
# headers: FLT_EVAL_METHOD is given as 0, which every target of the
# library has (it refuses to compile otherwise), and __GNUC__ as GCC's.
set -eu
root=$(cd "$1" && pwd)
out=$2
here=$(cd "$(dirname "$0")" && pwd)

addons=""
for d in /usr/lib/*/cppcheck/addons /usr/share/cppcheck/addons; do
    if [ -f "$d/misra.py" ]; then addons=$d; break; fi
done
[ -n "$addons" ] || { echo "analyse.sh: cppcheck's misra.py addon not found"; exit 1; }

defs_portable="-D__GNUC__=12 -DFLT_EVAL_METHOD=0"
defs_armv7em="$defs_portable -D__ARM_ARCH_7EM__=1 -D__thumb2__=1 -D__ARM_FP=4 -D__OPTIMIZE__=1"
# clang: the same two paths, compiled as the Makefile compiles them.
tidy_portable="-std=c11 -ffreestanding -ffp-contract=off -O2"
tidy_armv7em="$tidy_portable --target=arm-none-eabi -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"

# analyse CONFIG: both tools over a copy of the sources (cppcheck writes its
# dump files beside them); OUT/CONFIG.txt its findings.
analyse() {
    cfg=$1 tree=$out/$1
    mkdir -p "$tree/target"
    cp -R "$root/target/src" "$root/target/include" "$root/target/.clang-tidy" "$tree/target/"
    eval "defs=\$defs_$cfg"
    eval "tidy=\$tidy_$cfg"
    cd "$tree"
    # shellcheck disable=SC2086
    cppcheck --dump --quiet --std=c11 --platform=arm32-wchar_t4 -Itarget/include -Itarget/src $defs \
        --template='cppcheck {id} {file}:{line}:{column}' $sources 2>"$out/$cfg-cppcheck.txt" ||
        { cat "$out/$cfg-cppcheck.txt"; echo "analyse.sh: cppcheck failed ($cfg)"; return 1; }
    for s in $sources; do
        if ! grep -q '<token ' "$s.dump" 2>/dev/null; then
            cat "$out/$cfg-cppcheck.txt"; echo "analyse.sh: cppcheck did not analyse $s ($cfg)"; return 1
        fi
    done
    # The addon on each file, then its rules across files (5.x, 8.x) from the
    # .ctu-info files those runs wrote.  One process per file: given several
    # dump files at once, misra.py 2.10 writes the cross-file summaries of
    # the first only, and would miss Rules 5.9, 8.5 and 8.7.
    : >"$out/$cfg-misra.txt"
    for s in $sources; do
        d=$s.dump
        python3 -S "$addons/misra.py" --cli "$d" >>"$out/$cfg-misra.txt" 2>&1 ||
            { cat "$out/$cfg-misra.txt"; echo "analyse.sh: misra.py failed on $d ($cfg)"; return 1; }
    done
    # shellcheck disable=SC2046
    python3 -S "$addons/misra.py" --cli $(for s in $sources; do echo "$s.ctu-info"; done) >>"$out/$cfg-misra.txt" 2>&1 ||
        { cat "$out/$cfg-misra.txt"; echo "analyse.sh: misra.py failed on the .ctu-info files ($cfg)"; return 1; }
    # shellcheck disable=SC2086
    clang-tidy --quiet $sources -- $tidy -Itarget/include >"$out/$cfg-tidy.txt" 2>"$out/$cfg-tidy.err" ||
        { cat "$out/$cfg-tidy.txt" "$out/$cfg-tidy.err"; echo "analyse.sh: clang-tidy failed ($cfg)"; return 1; }
    python3 "$here/findings.py" "$tree" "$out/$cfg-cppcheck.txt" "$out/$cfg-misra.txt" "$out/$cfg-tidy.txt" \
        >"$out/$cfg.txt"
}

rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
# The configurations side by side (one core each).  MISRA_CONFIGS and
# MISRA_SOURCES (paths relative to ROOT) narrow the analysis, for the self-test.
sources=${MISRA_SOURCES:-target/src/*.c}
pids=""
for cfg in ${MISRA_CONFIGS:-portable armv7em}; do
    ( analyse "$cfg" ) &
    pids="$pids $!"
done
status=0
for p in $pids; do wait "$p" || status=1; done
[ "$status" = 0 ] || exit 1
LC_ALL=C sort -u $(for cfg in ${MISRA_CONFIGS:-portable armv7em}; do echo "$out/$cfg.txt"; done) >"$out/findings.txt"
