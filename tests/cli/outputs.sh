#!/bin/sh
# outputs.sh TISSUEFIT LIBTFIT RENAME_FAULT_SO — outputs that belong together
# (issue 19): NAME.h and NAME_golden.h change together or not at all, a
# mismatched pair does not compile, destinations are written as cp writes
# them, temporaries never stay behind, and text copied into generated
# comments cannot break the header.
set -u
tool=$1 lib=$2 fault=$3
. "$(dirname "$0")/expect.sh"
no_temporaries() {
    ls -A "$1" | grep -q '\.tmp' && bad "$2: temporary files left: $(ls -A "$1" | grep '\.tmp')"
}
cc_flags="-std=c11 -ffp-contract=off -Wall -Wextra -Werror -Itarget/include"
# Builds and runs the golden vectors of DIR/NAME.h; the compiler's messages in $tmp/cc.
golden_runs() { # DIR NAME
    up=$(echo "$2" | tr a-z A-Z)
    gcc $cc_flags -I"$1" -DGOLDEN_H="\"$2_golden.h\"" -DGOLDEN_SETS="TFIT_${up}_GOLDEN_SETS" \
        -DTFIT_${up}_IMPLEMENTATION tests/header/run_golden.c "$lib" -o "$tmp/golden" \
        >"$tmp/cc" 2>&1 && "$tmp/golden" "$2" >>"$tmp/cc" 2>&1
}

# --- destinations that are not regular files: refused before any work
d=$tmp/w
mkdir "$d/dir.h"
expect 2 "-o a directory" -- "$tool" -q demo-model -o "$d/dir.h"
says "-o a directory" "dir.h: exists and is not a regular file"
[ -e "$d/dir_golden.h" ] && bad "-o a directory still wrote dir_golden.h"
mkdir "$d/gold_golden.h"
expect 2 "a directory where the golden file goes" -- "$tool" -q demo-model -o "$d/gold.h"
[ -e "$d/gold.h" ] && bad "the header was written although its golden file could not be"
mkfifo "$d/fifo.h"
expect 2 "-o a FIFO (as -o /dev/full would be)" -- "$tool" -q demo-model -o "$d/fifo.h"
[ -p "$d/fifo.h" ] || bad "the FIFO was replaced by a file"
ln -s "$d/nothing.h" "$d/dangling.h"
expect 2 "-o a dangling symbolic link" -- "$tool" -q demo-model -o "$d/dangling.h"
says "dangling link" "a symbolic link to nothing"
rm -r "$d/dir.h" "$d/gold_golden.h" "$d/fifo.h" "$d/dangling.h"
nothing_written "refused destinations"

# --- a symbolic link is written through: the link stays
mkdir "$tmp/real"
echo "old" >"$tmp/real/target.h"
ln -s "$tmp/real/target.h" "$d/link.h"
expect 0 "-o a symbolic link" -- "$tool" -q demo-model -o "$d/link.h"
[ -L "$d/link.h" ] || bad "the symbolic link was replaced"
grep -q "TFIT_LINK_FORWARD_N_OUT" "$tmp/real/target.h" || bad "the link's target was not written"
no_temporaries "$tmp/real" "-o a symbolic link"
rm -f "$d"/*

# --- a pair, then a second run that cannot write (a full disk): nothing changes
expect 0 "demo-model, first run" -- "$tool" -q demo-model -o "$d/pair.h"
golden_runs "$d" pair || bad "the first pair does not run: $(cat "$tmp/cc")"
cp "$d/pair.h" "$tmp/pair.h.1" && cp "$d/pair_golden.h" "$tmp/pair_golden.h.1"
expect 1 "demo-model, second run on a full disk (ulimit -f)" -- \
    sh -c 'trap "" XFSZ; ulimit -f 200; exec "$0" -q demo-model --envelope 2 -o "$1"' "$tool" "$d/pair.h"
says "full disk" "write failed"
cmp -s "$d/pair.h" "$tmp/pair.h.1" && cmp -s "$d/pair_golden.h" "$tmp/pair_golden.h.1" ||
    bad "a failed write changed the pair"
no_temporaries "$d" "full disk"
expect 1 "fit on a full disk: exit 1, not 2" -- \
    sh -c 'trap "" XFSZ; ulimit -f 200; exec "$0" -q fit tests/solver/block48_seed.yaml -o "$1"' "$tool" "$d/fitted.h"
[ -e "$d/fitted.h" ] || [ -e "$d/fitted_golden.h" ] && bad "fit on a full disk left a file"
no_temporaries "$d" "fit on a full disk"

# --- SIGTERM at the first rename: held back until both are renamed, so the
# run dies of it with a whole new pair and no temporary
cp "$d/pair.h" "$d/keep.h"
expect 143 "SIGTERM at the first rename" -- env LD_PRELOAD="$fault" TF_RENAME_FAULT=1:15 \
    "$tool" -q demo-model --envelope 2 -o "$d/pair.h"
cmp -s "$d/pair.h" "$tmp/pair.h.1" && bad "SIGTERM split the pair (old header)"
golden_runs "$d" pair || bad "the pair after SIGTERM does not run: $(head -5 "$tmp/cc")"
no_temporaries "$d" "SIGTERM"
cp "$tmp/pair.h.1" "$d/pair.h" && cp "$tmp/pair_golden.h.1" "$d/pair_golden.h" && rm "$d/keep.h"

# --- SIGTERM while the temporaries are written (the second one just
# created): held back too, so no temporary stays behind
expect 143 "SIGTERM while writing the temporaries" -- env LD_PRELOAD="$fault" TF_MKSTEMP_FAULT=2:15 \
    "$tool" -q demo-model --envelope 3 -o "$d/pair.h"
no_temporaries "$d" "SIGTERM while writing"
golden_runs "$d" pair || bad "the pair after SIGTERM while writing does not run: $(head -5 "$tmp/cc")"
cp "$tmp/pair.h.1" "$d/pair.h" && cp "$tmp/pair_golden.h.1" "$d/pair_golden.h"

# --- SIGINT and SIGTERM sent to the process while fit writes, as a shell
# sends them: the kernel hands them to any thread that does not block them,
# and fit's OpenMP workers exist; held back all the same
for sig in 2:130 15:143; do
    expect "${sig#*:}" "signal ${sig%:*} sent to fit's process while writing" -- \
        env LD_PRELOAD="$fault" TF_MKSTEMP_KILL="2:${sig%:*}" OMP_NUM_THREADS=2 \
        "$tool" -q fit tests/solver/block48_seed.yaml -o "$d/pair.h"
    no_temporaries "$d" "signal ${sig%:*} sent to the process"
    golden_runs "$d" pair || bad "the pair after signal ${sig%:*} does not run: $(head -5 "$tmp/cc")"
done
cp "$tmp/pair.h.1" "$d/pair.h" && cp "$tmp/pair_golden.h.1" "$d/pair_golden.h"

# --- killed between the two renames: a new golden file beside the old
# header, which the golden runner refuses to compile
expect 137 "SIGKILL between the renames" -- env LD_PRELOAD="$fault" TF_RENAME_FAULT=2:9 \
    "$tool" -q demo-model --envelope 2 -o "$d/pair.h"
cmp -s "$d/pair.h" "$tmp/pair.h.1" || bad "the header changed before its rename"
cmp -s "$d/pair_golden.h" "$tmp/pair_golden.h.1" && bad "the golden file was not renamed first"
if golden_runs "$d" pair; then
    bad "a golden file beside a header of another run compiled and ran"
else
    grep -q "pair_golden.h and pair.h are not from the same run of tissuefit" "$tmp/cc" ||
        bad "the mismatch is not named: $(head -5 "$tmp/cc")"
fi
rm -f "$d"/pair.h.tmp.*
expect 0 "demo-model, rerun after the crash" -- "$tool" -q demo-model --envelope 2 -o "$d/pair.h"
golden_runs "$d" pair || bad "the regenerated pair does not run: $(cat "$tmp/cc")"
rm -f "$d"/*

# --- hostile text copied into generated comments
hdir="$tmp/a*/b/*c??/"
mkdir -p "$hdir"
cp tests/solver/block48_seed.yaml "$hdir/scene.yaml"
expect 0 "fit from a path with */ /* ??/ and a --set with a comment" -- "$tool" -q fit \
    "$hdir/scene.yaml" --set 'fit.train=100 #*/ junk ??/' --set 'contact.0.name=x*/y/*z??/' \
    -o "$d/hostile.h"
golden_runs "$d" hostile || bad "a header from hostile names does not compile: $(head -20 "$tmp/cc")"
printf '#include "hostile_golden.h"\nint main(void) { return 0; }\n' |
    clang $cc_flags -I"$d" -DTFIT_HOSTILE_IMPLEMENTATION -fsyntax-only -x c - >"$tmp/cc" 2>&1 ||
    bad "clang rejects it: $(head -20 "$tmp/cc")"
grep -q '^ \* scene: .*a\* /b/' "$d/hostile.h" || bad "the scene path is not in the banner"

finish outputs
