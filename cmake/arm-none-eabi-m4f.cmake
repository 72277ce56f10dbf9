# arm-none-eabi-m4f.cmake — CMake toolchain file for Cortex-M4F firmware
# (STM32F4-class; QEMU's mps2-an386) with Debian's gcc-arm-none-eabi:
#
#   cmake -S . -B build-m4f -DCMAKE_TOOLCHAIN_FILE=.../arm-none-eabi-m4f.cmake
#
# The core flags are those of the Makefile's cross builds (M4F_FLAGS): hard
# float on the single-precision FPv4 unit.  Images link without libc or
# startup files (linker/startup.c is the reset handler; add -T BOARD.ld and
# -L${TFIT_LINKER_DIR}).  TFIT_CORE tells find_package(tfit) which installed
# archive to link (lib/tfit/cortex-m4f/libtfit.a).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(TFIT_ARM_PREFIX "arm-none-eabi-" CACHE STRING "prefix of the cross tools")
set(CMAKE_C_COMPILER "${TFIT_ARM_PREFIX}gcc")
set(CMAKE_ASM_COMPILER "${TFIT_ARM_PREFIX}gcc")
set(CMAKE_AR "${TFIT_ARM_PREFIX}ar" CACHE FILEPATH "")
set(CMAKE_RANLIB "${TFIT_ARM_PREFIX}ranlib" CACHE FILEPATH "")
set(CMAKE_OBJCOPY "${TFIT_ARM_PREFIX}objcopy" CACHE FILEPATH "")
set(CMAKE_SIZE "${TFIT_ARM_PREFIX}size" CACHE FILEPATH "")

set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -Wl,--gc-sections -Wl,--no-undefined")
# The compiler checks cannot link an image without a linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(TFIT_CORE cortex-m4f CACHE STRING "libtfit core to link when cross-compiling")

# Programs (the tissuefit tool) from the build machine; libraries, headers
# and packages from the cross prefixes only (CMAKE_FIND_ROOT_PATH or, when it
# is empty, the paths given, e.g. CMAKE_PREFIX_PATH).
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
