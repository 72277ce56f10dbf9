# arm-none-eabi-m4f.cmake — CMake toolchain file for Cortex-M4F firmware
# (STM32F4-class; QEMU's mps2-an386):
#
#   cmake -S . -B build-m4f -DCMAKE_TOOLCHAIN_FILE=.../arm-none-eabi-m4f.cmake
#
# The core flags are those of the Makefile's cross builds (M4F_FLAGS): hard
# float on the single-precision FPv4 unit; the rest is arm-none-eabi.cmake.
set(TFIT_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(TFIT_CORE_DEFAULT cortex-m4f)
include("${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake")
