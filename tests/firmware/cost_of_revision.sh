#!/bin/sh
# cost_of_revision.sh REVISION [HEADER] — Cortex-M4F cost of the evaluator
# as it was at a git revision: builds that revision's target library (-O2,
# as target.mk does), runs HEADER's golden vectors on mps2-an386 under a
# QEMU trace, and prints the instructions and cycles (host/cost/cycles.c cost
# table) of each golden set.  Used for the before/after table of
# docs/firmware.md; run from the top of the repository after `make
# check-cycles` (it needs build/tests/trace_mix and check_cycle_model).
#   tests/firmware/cost_of_revision.sh 3a16b3a build/tests/gen/haptic.h
set -eu
rev=$1
header=${2:-build/tests/gen/haptic.h}
name=$(basename "$header" .h)
upper=$(echo "$name" | tr a-z A-Z)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
flags="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
git archive "$rev" target/src target/include | tar -x -C "$tmp"
for f in "$tmp"/target/src/*.c; do
    arm-none-eabi-gcc -std=c11 -ffp-contract=off -O2 -ffreestanding -ffunction-sections \
        -fdata-sections $flags -I"$tmp/target/include" -c "$f" -o "${f%.c}.o"
done
arm-none-eabi-ld -r "$tmp"/target/src/*.o -o "$tmp/libtfit.o"
arm-none-eabi-ar rcs "$tmp/libtfit.a" "$tmp/libtfit.o"
arm-none-eabi-gcc -std=c11 -O2 -ffreestanding -ffunction-sections -fdata-sections $flags \
    -I"$tmp/target/include" -Ilinker -I"$(dirname "$header")" \
    -DGOLDEN_H="\"${name}_golden.h\"" -DGOLDEN_SETS="TFIT_${upper}_GOLDEN_SETS" \
    -DTFIT_"${upper}"_IMPLEMENTATION -DLABEL="\"$rev\"" tests/firmware/qemu_golden.c \
    linker/startup.c linker/semihost.c "$tmp/libtfit.a" -nostdlib -Wl,--gc-sections -Llinker \
    -T mps2-an386.ld -o "$tmp/image.elf"
timeout 300 qemu-system-arm -M mps2-an386 -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "$tmp/image.elf" \
    -d in_asm,exec,nochain -D "$tmp/trace.log" >/dev/null 2>&1
arm-none-eabi-objdump -d --no-show-raw-insn "$tmp/image.elf" >"$tmp/image.dis"
build/tests/trace_mix "$tmp/image.dis" "$tmp/trace.log" >"$tmp/trace.txt"
echo "$rev, $header, Cortex-M4F:"
build/tests/check_cycle_model cost m4f "$tmp/trace.txt"
