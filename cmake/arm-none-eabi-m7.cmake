# arm-none-eabi-m7.cmake — CMake toolchain file for Cortex-M7 firmware
# (STM32H7-class; QEMU's mps2-an500):
#
#   cmake -S . -B build-m7 -DCMAKE_TOOLCHAIN_FILE=.../arm-none-eabi-m7.cmake
#
# The core flags are those of the Makefile's cross builds (M7_FLAGS): hard
# float on the double-precision FPv5 unit; the rest is arm-none-eabi.cmake.
set(TFIT_ARM_FLAGS "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
set(TFIT_CORE_DEFAULT cortex-m7)
include("${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake")
