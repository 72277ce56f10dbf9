# tfitTargets.cmake — the imported targets of an installed tissuefit.
#
# `make install` installs the libtfit.a archives the Makefile built and
# tested (check-bitexact, check-qemu): the native one as lib/libtfit.a, and
# each core of INSTALL_CORES as lib/tfit/CORE/libtfit.a (the name stays
# libtfit.a: linker/sections.ld places the library's code by it).  This file
# describes them; nothing is compiled here.  Paths are relative to this file,
# so the prefix can move (DESTDIR, a copied tree).
get_filename_component(_tfit_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

if(CMAKE_CROSSCOMPILING)
    set(TFIT_CORE "" CACHE STRING "libtfit core to link when cross-compiling (lib/tfit/CORE/libtfit.a)")
    file(GLOB _tfit_cores RELATIVE "${_tfit_prefix}/lib/tfit" "${_tfit_prefix}/lib/tfit/*/libtfit.a")
    string(REPLACE "/libtfit.a" "" _tfit_cores "${_tfit_cores}")
    string(REPLACE ";" ", " _tfit_cores "${_tfit_cores}")
    if(_tfit_cores STREQUAL "")
        set(_tfit_cores "none (make install INSTALL_CORES=\"cortex-m4f ...\")")
    endif()
    if(TFIT_CORE STREQUAL "")
        set(tfit_FOUND FALSE)
        string(CONCAT tfit_NOT_FOUND_MESSAGE "cross-compiling: set TFIT_CORE to the core to link (the "
            "toolchain files arm-none-eabi-m4f.cmake and -m7.cmake set cortex-m4f and cortex-m7); "
            "installed: ${_tfit_cores}")
        return()
    endif()
    set(_tfit_lib "${_tfit_prefix}/lib/tfit/${TFIT_CORE}/libtfit.a")
else()
    set(_tfit_lib "${_tfit_prefix}/lib/libtfit.a")
endif()
if(NOT EXISTS "${_tfit_lib}")
    set(tfit_FOUND FALSE)
    set(tfit_NOT_FOUND_MESSAGE "${_tfit_lib} is not installed")
    if(CMAKE_CROSSCOMPILING)
        string(APPEND tfit_NOT_FOUND_MESSAGE "; installed cores: ${_tfit_cores}")
    endif()
    return()
endif()

if(NOT TARGET tfit::tfit)
    add_library(tfit::tfit STATIC IMPORTED)
    # The flags a consumer needs, as target/CMakeLists.txt gives them PUBLIC:
    # C11; no contraction of a*b + c; one section per function and per table,
    # so that the linker scripts put the library's code and a generated
    # header's tables (.rodata.tfit_NAME_coef, _dims, _nodes) in fast memory.
    set_target_properties(tfit::tfit PROPERTIES
        IMPORTED_LOCATION "${_tfit_lib}"
        IMPORTED_LINK_INTERFACE_LANGUAGES C
        INTERFACE_INCLUDE_DIRECTORIES "${_tfit_prefix}/include"
        INTERFACE_COMPILE_FEATURES c_std_11
        INTERFACE_COMPILE_OPTIONS
            "$<$<C_COMPILER_ID:GNU,Clang,AppleClang>:-ffp-contract=off;-ffunction-sections;-fdata-sections>")
endif()

if(NOT TARGET tfit::tissuefit AND EXISTS "${_tfit_prefix}/bin/tissuefit")
    add_executable(tfit::tissuefit IMPORTED)
    set_target_properties(tfit::tissuefit PROPERTIES IMPORTED_LOCATION "${_tfit_prefix}/bin/tissuefit")
endif()

# Cortex-M: the linker scripts, the startup code and QEMU's semihosting.
set(TFIT_LINKER_DIR "${_tfit_prefix}/share/tfit/linker")
set(TFIT_TOOLCHAIN_DIR "${_tfit_prefix}/share/tfit/cmake")
foreach(_tfit_part IN ITEMS startup semihost)
    if(NOT TARGET tfit::${_tfit_part})
        add_library(tfit::${_tfit_part} INTERFACE IMPORTED)
        set_target_properties(tfit::${_tfit_part} PROPERTIES
            INTERFACE_SOURCES "${TFIT_LINKER_DIR}/${_tfit_part}.c"
            INTERFACE_INCLUDE_DIRECTORIES "${TFIT_LINKER_DIR}")
    endif()
endforeach()

set(tfit_LIBRARY "${_tfit_lib}")
unset(_tfit_lib)
unset(_tfit_cores)
unset(_tfit_part)
unset(_tfit_prefix)
