#!/bin/sh
# check_consumers.sh WORK VERSION — check-cmake's runs (tests/cmake.mk).
#
# WORK/prefix holds `make install INSTALL_CORES="cortex-m4f cortex-m7"`.  Builds, outside
# the tree's build, the consumer projects of tests/cmake/:
#   consumer_find    find_package(tfit) natively and for Cortex-M4F and
#                    Cortex-M7 (the installed toolchain files; QEMU
#                    mps2-an386, mps2-an500);
#   consumer_vendor  add_subdirectory(target) natively and for Cortex-M4F;
# runs their golden programs (0 mismatching words, and the planted program
# must fail with exactly one), checks the flags every compile got, the
# placement of the library's code and a header's tables in the Cortex-M
# images, the build-time regeneration of tfit_generate_header(), the
# version requests tfitConfigVersion.cmake accepts, and that -ffast-math is
# refused.  Prints one line per fact; exits 1 at the first failure.
set -eu
work=$1 version=$2
top=$(pwd)
prefix=$work/prefix
jobs=${CMAKE_JOBS:-2}
fail() { echo "FAIL: $*"; exit 1; }

# configure PROJECT BUILD ARGS...: cmake -S tests/cmake/PROJECT -B WORK/BUILD
# ARGS, its output in WORK/BUILD.log (shown if it fails).
configure() {
    src=$1 dir=$work/$2
    shift 2
    cmake -S "$top/tests/cmake/$src" -B "$dir" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "$@" \
        >"$dir.log" 2>&1 || { cat "$dir.log"; fail "cmake -S tests/cmake/$src ($*)"; }
}
build() {
    cmake --build "$work/$1" -j "$jobs" >>"$work/$1.log" 2>&1 || { cat "$work/$1.log"; fail "build of $1"; }
}

# run BUILD PROGRAM: a golden program must pass; its _planted twin must fail
# with exactly one mismatching word.  Cortex-M images run under QEMU.
run() {
    dir=$work/$1 prog=$2
    case $1 in
    *-m4f) qemu="$top/tests/firmware/qemu_run.sh mps2-an386" suffix=.elf ;;
    *-m7) qemu="$top/tests/firmware/qemu_run.sh mps2-an500" suffix=.elf ;;
    *) qemu="" suffix="" ;;
    esac
    if ! out=$($qemu "$dir/$prog$suffix" 2>&1); then
        printf '%s\n' "$out"
        fail "$1/$prog"
    fi
    printf '%s\n' "$out"
    [ "$(printf '%s\n' "$out" | grep -c ' 0 failed .* 0 mismatching)$')" = 2 ] ||
        fail "$1/$prog: not the two result lines (float, q31) with 0 mismatching words"
    [ "$prog" = golden_block48 ] || return 0
    if out=$($qemu "$dir/${prog}_planted$suffix" 2>&1); then
        printf '%s\n' "$out"
        fail "$1/${prog}_planted passed: a mismatching word would go unnoticed"
    fi
    printf '%s\n' "$out" | grep -q 'float: 1 passed, 1 failed .* 1 mismatching)$' ||
        { printf '%s\n' "$out"; fail "$1/${prog}_planted: not the one planted mismatch"; }
    echo "$1/${prog}_planted: fails with the one planted mismatching word: ok"
}

# flags BUILD FILE-PATTERN FLAG...: every compile of a matching file has every
# flag (compile_commands.json; "!FLAG": has not).
flags() {
    b=$1 pattern=$2
    shift 2
    lines=$(grep '"command":' "$work/$b/compile_commands.json" | grep -E -- "-c [^ ]*$pattern\"" || true)
    [ -n "$lines" ] || fail "$b: no compile of $pattern in compile_commands.json"
    for f in "$@"; do
        case $f in
        !*) if printf '%s\n' "$lines" | grep -q -- " ${f#!} "; then fail "$b: a compile of $pattern has ${f#!}"; fi ;;
        *) if printf '%s\n' "$lines" | grep -v -q -- " $f "; then fail "$b: a compile of $pattern lacks $f"; fi ;;
        esac
    done
    echo "$b: $(printf '%s\n' "$lines" | wc -l) compile(s) of $(printf '%s' "$pattern" | tr -d '\\')" \
         "with $(printf '%s' "$*" | sed 's/!/no /g'): ok"
}

# placed BUILD PROGRAM: the library's code lies in .fast_text and the
# header's coefficient table in .fast_rodata (linker/sections.ld).
placed() {
    elf=$work/$1/$2.elf
    nm=$(arm-none-eabi-nm "$elf")
    addr() { printf '%s\n' "$nm" | awk -v s="$1" '$3 == s { print $1 }'; }
    within() {
        a=$(addr "$1") lo=$(addr "__$2_start") hi=$(addr "__$2_end")
        [ -n "$a" ] && [ -n "$lo" ] && [ -n "$hi" ] || fail "$elf lacks $1 or the bounds of .$2"
        [ $((0x$a >= 0x$lo && 0x$a < 0x$hi)) = 1 ] || fail "$1 at 0x$a is outside .$2 [0x$lo, 0x$hi)"
    }
    for s in tfit_displacements tfit_model_check tfit_golden_run; do within $s fast_text; done
    within tfit_block48_forward_coef fast_rodata
    echo "$1/$2: library code in .fast_text, tfit_block48_forward_coef in .fast_rodata: ok"
}

major=${version%%.*}
minor=${version#*.}
minor=${minor%%.*}
toolchain=$prefix/share/tfit/cmake/arm-none-eabi-m4f.cmake
cp "$top/tests/solver/block48_seed.yaml" "$work/seed48.yaml"
find_args="-DCMAKE_PREFIX_PATH=$prefix -DTFIT_REQUEST=$major.$minor -DTFIT_COEFFS_DIR=$top/coeffs \
-DTFIT_SCENE=$work/seed48.yaml"
vendor_args="-DTFIT_SOURCE_DIR=$top -DTFIT_COEFFS_DIR=$top/coeffs -DTFIT_WERROR=ON"

# --- which version requests the installed package meets (SameMajorVersion)
set -- "$major.$minor:found" "$major:found" "$major.$minor...<$((major + 1)):found" \
       "$major.$((minor + 1)):not found" "$((major + 1)):not found" "$major...$((major + 1)).0:not found"
requests=""
for req in "$@"; do requests="$requests${requests:+;}${req%%:*}"; done
configure version_probe probe -DCMAKE_PREFIX_PATH="$prefix" "-DREQUESTS=$requests"
for req in "$@"; do
    grep -q "tfit ${req%%:*}: ${req#*:}" "$work/probe.log" ||
        { cat "$work/probe.log"; fail "find_package(tfit ${req%%:*}) is not '${req#*:}'"; }
done
echo "find_package(tfit REQUEST) against $version: $major.$minor, $major and $major.$minor...<$((major + 1))" \
     "found; $major.$((minor + 1)), $((major + 1)) and $major...$((major + 1)).0 not: ok"

# --- find_package(tfit), native
# shellcheck disable=SC2086
configure consumer_find find $find_args
build find
run find golden_block48
run find golden_seed48
flags find 'tests/cmake/common/golden_run\.c' -ffp-contract=off -ffunction-sections -fdata-sections -std=c11
# tfit_generate_header(): nothing to do while the scene is unchanged; the
# header regenerated (and its program relinked) once it changes.
cmake --build "$work/find" -j "$jobs" >"$work/find-again.log" 2>&1 || { cat "$work/find-again.log"; fail "rebuild"; }
if grep -q 'tissuefit fit' "$work/find-again.log"; then fail "seed48.h regenerated with its scene unchanged"; fi
touch "$work/seed48.yaml"
cmake --build "$work/find" -j "$jobs" >"$work/find-touched.log" 2>&1 || { cat "$work/find-touched.log"; fail "rebuild"; }
grep -q 'tissuefit fit .*seed48.yaml -> seed48.h' "$work/find-touched.log" || fail "seed48.h not regenerated after its scene changed"
grep -q 'Linking C executable golden_seed48$' "$work/find-touched.log" || fail "golden_seed48 not relinked after seed48.h changed"
echo "find: tfit_generate_header() reruns tissuefit only when the scene changed: ok"

# --- find_package(tfit), Cortex-M4F with the installed toolchain file, under QEMU
# shellcheck disable=SC2086
configure consumer_find find-m4f $find_args -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release
build find-m4f
run find-m4f golden_block48
run find-m4f golden_seed48
flags find-m4f 'tests/cmake/common/golden_run\.c' -ffp-contract=off -fdata-sections -mcpu=cortex-m4 -mfloat-abi=hard
placed find-m4f golden_block48

# --- the same for Cortex-M7 (the installed arm-none-eabi-m7.cmake; QEMU mps2-an500)
# shellcheck disable=SC2086
configure consumer_find find-m7 $find_args -DCMAKE_TOOLCHAIN_FILE="${toolchain%-m4f.cmake}-m7.cmake" \
    -DCMAKE_BUILD_TYPE=Release
build find-m7
run find-m7 golden_block48
flags find-m7 'tests/cmake/common/golden_run\.c' -ffp-contract=off -fdata-sections -mcpu=cortex-m7 \
      -mfpu=fpv5-d16 -mfloat-abi=hard
grep -q "lib/tfit/cortex-m7/libtfit.a" "$work/find-m7/CMakeFiles/golden_block48.dir/link.txt" ||
    fail "find-m7: golden_block48 does not link lib/tfit/cortex-m7/libtfit.a"
placed find-m7 golden_block48

# --- add_subdirectory(target), native and Cortex-M4F
# shellcheck disable=SC2086
configure consumer_vendor vendor $vendor_args
build vendor
run vendor golden_block48
flags vendor 'target/src/[a-z0-9_]+\.c' -std=c11 -ffp-contract=off -ffreestanding -ffunction-sections \
      -fdata-sections -Werror '!-ffast-math'
flags vendor 'tests/cmake/common/golden_run\.c' -ffp-contract=off -fdata-sections '!-ffreestanding'
n_src=$(ls "$top"/target/src/*.c | wc -l)
n_lib=$(grep -c '"command":.*-c [^ ]*target/src/' "$work/vendor/compile_commands.json")
[ "$n_src" = "$n_lib" ] || fail "vendor: libtfit compiles $n_lib sources, target/src has $n_src"
[ -f "$work/vendor/tfit/libtfit.a" ] || fail "vendor: the library is not named libtfit.a"
echo "vendor: libtfit.a from all $n_src target/src/*.c: ok"
# shellcheck disable=SC2086
configure consumer_vendor vendor-m4f $vendor_args -DCMAKE_TOOLCHAIN_FILE="$top/cmake/arm-none-eabi-m4f.cmake" \
    -DCMAKE_BUILD_TYPE=Release
build vendor-m4f
run vendor-m4f golden_block48
placed vendor-m4f golden_block48

# --- -ffast-math is refused (the native vendor build reconfigured: its tests are done)
if cmake "$work/vendor" -DCMAKE_C_FLAGS=-ffast-math >"$work/fastmath.log" 2>&1; then
    fail "add_subdirectory(target) accepted -ffast-math"
fi
grep -q 'tfit: -ffast-math in the C flags changes float results' "$work/fastmath.log" ||
    { cat "$work/fastmath.log"; fail "-ffast-math refused for another reason"; }
echo "vendor: CMAKE_C_FLAGS=-ffast-math refused at configure time: ok"
