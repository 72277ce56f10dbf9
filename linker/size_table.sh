#!/bin/sh
# size_table.sh IMAGE.elf... — flash and RAM of firmware images, from
# arm-none-eabi-objdump -h (section sizes, run and load addresses) and nm
# (symbol sizes):
#   flash   everything stored in non-volatile memory (load addresses in the
#           STM32 flash at 0x08000000), including the copies of .fast_text
#           and .data
#   library libtfit's code (.fast_text: ITCM on the M7, flash on the M4F)
#   models  the model tables (tfit_*_coef, _dims, _nodes: .fast_rodata, in
#           CCM/DTCM, copied from flash) and descriptors
#   RAM     .data + .bss (the example's output buffer) + the reserved stack
#           + tables copied to CCM/DTCM + code copied to ITCM
set -eu
printf '%-28s %8s %8s %8s %8s %8s  %s\n' image flash library models RAM stack "RAM regions"
for img in "$@"; do
    core=$(basename "$(dirname "$img")")
    name=$(basename "$img" .elf)
    models=$(arm-none-eabi-nm -S --radix=d "$img" | awk '
        NF == 4 { size[$4] = $2 + 0 }
        END {
            for (n in size) if (n ~ /^tfit_.*_coef$/) {
                m = substr(n, 1, length(n) - 5)
                s += size[n] + size[m "_dims"] + size[m "_nodes"] + size[m]
            }
            print s + 0
        }')
    arm-none-eabi-objdump -h "$img" | awk -v label="$core/$name" -v models="$models" '
        BEGIN { FLASH_LO = 134217728; FLASH_HI = 268435456 } # 0x08000000, 0x10000000
        function hex(s,    i, n) {
            n = 0; s = tolower(s)
            for (i = 1; i <= length(s); i++) n = n * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
            return n
        }
        $2 ~ /^\./ && NF >= 6 {
            name = $2; size = hex($3); vma = hex($4); lma = hex($5)
            getline flags
            if (size == 0 || flags !~ /ALLOC/) next
            inflash = (lma >= FLASH_LO && lma < FLASH_HI)
            if (flags ~ /LOAD/ && inflash) flash += size
            if (name == ".fast_text") lib = size
            if (!(vma >= FLASH_LO && vma < FLASH_HI)) {
                ram += size
                region = sprintf("%s%s%s@0x%08x", region, region ? " " : "", name, vma)
            }
            if (name == ".stack") stack = size
        }
        END { printf "%-28s %8d %8d %8d %8d %8d  %s\n", label, flash, lib, models, ram, stack, region }'
done
