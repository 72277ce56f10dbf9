#!/bin/sh
# contract_lib.sh OUT.a SRCDIR FLAGS... — builds libtfit.a for the Cortex-M4F
# from SRCDIR/*.c with the given compiler flags (no -std/-ffp-contract of
# target.mk's own), the way a user's own build would: for check-contract
# (linker/firmware.mk), which shows what such builds do and what catches
# them.  Exits non-zero when a file does not compile.
set -eu
out=$1 src=$2
shift 2
dir=$(dirname "$out")/obj
rm -rf "$dir"
mkdir -p "$dir"
for f in "$src"/*.c; do
    arm-none-eabi-gcc "$@" -O2 -ffreestanding -ffunction-sections -fdata-sections \
        -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Itarget/include -I"$src" \
        -c "$f" -o "$dir/$(basename "${f%.c}").o"
done
arm-none-eabi-ld -r "$dir"/*.o -o "$dir/libtfit.o"
rm -f "$out"
arm-none-eabi-ar rcs "$out" "$dir/libtfit.o"
