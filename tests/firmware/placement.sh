#!/bin/sh
# placement.sh OUT LDSCRIPT — the library's sources compiled into a
# haptic-loop image instead of linked as libtfit.a (docs/firmware.md §2),
# with CFLAGS and LDFLAGS from the environment (the image's own):
#  - compiled to objects named tfit_*.o, as a build system names them, the
#    evaluator lands in .fast_text as it does from the archive
#    (tfit_contact_force between __fast_text_start and __fast_text_end);
#  - compiled and linked by one gcc command (random object names), the
#    link stops with linker/sections.ld's message.
set -eu
out=$1 script=$2
gcc=${ARMGCC:-arm-none-eabi-gcc}
app="target/examples/haptic_loop.c target/examples/board_stm32.c linker/startup.c"
rm -rf "$out" && mkdir -p "$out"
for f in target/src/*.c; do
    $gcc $CFLAGS -c "$f" -o "$out/$(basename "$f" .c).o"
done
# shellcheck disable=SC2086  # flag lists
$gcc $CFLAGS $app "$out"/tfit_*.o $LDFLAGS -T "$script" -o "$out/objects.elf"
addr() { ${gcc%gcc}nm "$out/objects.elf" | awk -v s="$1" '$3 == s { print $1 }'; }
a=$(addr tfit_contact_force) lo=$(addr __fast_text_start) hi=$(addr __fast_text_end)
[ -n "$a" ] && [ $((0x$a)) -ge $((0x$lo)) ] && [ $((0x$a)) -lt $((0x$hi)) ] ||
    { echo "$script: tfit_contact_force at 0x$a, outside .fast_text [0x$lo, 0x$hi)"; exit 1; }
# shellcheck disable=SC2086
if $gcc $CFLAGS $app target/src/*.c $LDFLAGS -T "$script" -o "$out/one.elf" >"$out/one.log" 2>&1; then
    echo "$script: sources compiled and linked in one command: linked, with the evaluator outside .fast_text"
    exit 1
fi
grep -q "is not in .fast_text: link libtfit.a, or compile target/src/\*.c to objects named tfit_\*.o" "$out/one.log" ||
    { cat "$out/one.log"; echo "$script: the one-command link failed for another reason"; exit 1; }
echo "$script: sources as tfit_*.o: tfit_contact_force at 0x$a in .fast_text [0x$lo, 0x$hi); one gcc command: refused at link"
