#!/bin/sh
# check.sh LABEL PREFIX LIBDIR [ARM]
# Freestanding proof for one cross build of the target library (built by the
# Makefile into LIBDIR/libtfit.a, one relocatable object inside):
#   1. `${PREFIX}nm -u` lists no undefined symbol (no libc, libm, libgcc);
#   2. the library has no .data or .bss (no static mutable state);
#   3. it links into an image with -nostdlib and --no-undefined;
#   4. (ARM) the linked image's call graph has no cycle and no indirect call.
set -eu
label=$1 prefix=$2 dir=$3 arm=${4:-}
lib=$dir/libtfit.a
fail=0
und=$("${prefix}nm" -u "$lib" | awk 'NF == 2 { print $2 }')
if [ -n "$und" ]; then
    echo "$label: undefined symbols: $und"
    fail=1
fi
state=$("${prefix}size" -A "$lib" | awk '$1 ~ /^\.(data|bss|sdata|sbss)/ && $2 > 0 { print $1 "=" $2 }')
if [ -n "$state" ]; then
    echo "$label: mutable static state: $state"
    fail=1
fi
entry=tfit_displacements
"${prefix}gcc" -nostdlib -nostartfiles -Wl,--no-undefined -Wl,-e,$entry \
    -Wl,-u,tfit_model_check -Wl,-u,tfit_contact_force -Wl,-u,tfit_golden_run \
    -Wl,-u,tfit_model_crc32 $FLAGS -o "$dir/image.elf" "$lib" || fail=1
if [ -n "$arm" ] && [ -f "$dir/image.elf" ]; then
    # the one indirect call: the modal rows' table by rank (tfit_modal_armv7em.c)
    modal_rows=tfit_modal_rows_asm=tfit_modal_rows_r1,tfit_modal_rows_r2,tfit_modal_rows_r3,tfit_modal_rows_r4,tfit_modal_rows_r5,tfit_modal_rows_r6,tfit_modal_rows_r7,tfit_modal_rows_r8
    "${prefix}objdump" -d "$dir/image.elf" | "$CALLGRAPH" "$modal_rows" >"$dir/callgraph.txt" || {
        cat "$dir/callgraph.txt"
        fail=1
    }
fi
text=$("${prefix}size" -A "$lib" | awk '$1 ~ /^\.text/ { t += $2 } END { print t }')
if [ "$fail" = 0 ]; then
    echo "$label: freestanding ok (no undefined symbols, no .data/.bss, links with -nostdlib${arm:+, no recursion}); .text $text bytes"
fi
exit $fail
