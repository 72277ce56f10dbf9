# tfitConfig.cmake — find_package(tfit) for an installed tissuefit
# (`make install PREFIX=...`; docs/firmware.md §11):
#
#   tfit::tfit       libtfit.a, its headers and the flags a consumer needs
#                    (tfitTargets.cmake); cross-compiling, the archive of the
#                    core named by TFIT_CORE (the toolchain file sets it)
#   tfit::tissuefit  the host tool, when it was installed
#   tfit::startup    linker/startup.c of the Cortex-M images, and
#   tfit::semihost   QEMU's semihosting console (linker/semihost.c)
#   TFIT_LINKER_DIR  the linker scripts: -L${TFIT_LINKER_DIR} -T stm32f407.ld
#   TFIT_TOOLCHAIN_DIR  toolchain files (arm-none-eabi-m4f.cmake, arm-none-eabi-m7.cmake)
#   tfit_generate_header(NAME ... SCENE ... OUTPUT_DIR ...)  (tfitGenerate.cmake)
include("${CMAKE_CURRENT_LIST_DIR}/tfitTargets.cmake")
if(NOT tfit_FOUND STREQUAL "FALSE")
    include("${CMAKE_CURRENT_LIST_DIR}/tfitGenerate.cmake")
endif()
