# arm-none-eabi.cmake — what the Cortex-M toolchain files share
# (arm-none-eabi-m4f.cmake, arm-none-eabi-m7.cmake set TFIT_ARM_FLAGS, the
# core's flags, and TFIT_CORE_DEFAULT, then include this) with Debian's
# gcc-arm-none-eabi.  Images link without libc or startup files
# (linker/startup.c is the reset handler; add -T BOARD.ld and
# -L${TFIT_LINKER_DIR}).  TFIT_CORE tells find_package(tfit) which installed
# archive to link (lib/tfit/CORE/libtfit.a).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(TFIT_ARM_PREFIX "arm-none-eabi-" CACHE STRING "prefix of the cross tools")
set(CMAKE_C_COMPILER "${TFIT_ARM_PREFIX}gcc")
set(CMAKE_ASM_COMPILER "${TFIT_ARM_PREFIX}gcc")
set(CMAKE_AR "${TFIT_ARM_PREFIX}ar" CACHE FILEPATH "")
set(CMAKE_RANLIB "${TFIT_ARM_PREFIX}ranlib" CACHE FILEPATH "")
set(CMAKE_OBJCOPY "${TFIT_ARM_PREFIX}objcopy" CACHE FILEPATH "")
set(CMAKE_SIZE "${TFIT_ARM_PREFIX}size" CACHE FILEPATH "")

set(CMAKE_C_FLAGS_INIT "${TFIT_ARM_FLAGS}")
set(CMAKE_ASM_FLAGS_INIT "${TFIT_ARM_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -Wl,--gc-sections -Wl,--no-undefined")
# The compiler checks cannot link an image without a linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(TFIT_CORE "${TFIT_CORE_DEFAULT}" CACHE STRING "libtfit core to link when cross-compiling")

# Programs (the tissuefit tool) from the build machine; libraries, headers
# and packages from the cross prefixes only (CMAKE_FIND_ROOT_PATH or, when it
# is empty, the paths given, e.g. CMAKE_PREFIX_PATH).
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
