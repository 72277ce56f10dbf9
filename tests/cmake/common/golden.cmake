# golden.cmake — shared by the consumer projects in tests/cmake/: one program
# that runs the golden vectors of a generated header (golden_run.c).
#
#   tfit_golden_program(TARGET NAME HEADER_DIR [PLANT])
#
# builds TARGET from golden_run.c for the header HEADER_DIR/NAME.h and its
# NAME_golden.h, linked with tfit::tfit; PLANT builds the variant that must
# report one mismatching word.  Cross-compiling for Cortex-M, the program is
# an image for QEMU's mps2-an386 (Cortex-M4F) or mps2-an500 (TFIT_CORE
# cortex-m7) (linker/BOARD.ld, startup.c, semihost.c), linked with a map
# file beside it.
function(tfit_golden_program target name header_dir)
    cmake_parse_arguments(PARSE_ARGV 3 ARG "PLANT" "" "")
    string(TOUPPER "${name}" upper)
    add_executable(${target} "${CMAKE_CURRENT_LIST_DIR}/../common/golden_run.c")
    target_link_libraries(${target} PRIVATE tfit::tfit)
    target_include_directories(${target} PRIVATE "${header_dir}")
    set_target_properties(${target} PROPERTIES C_STANDARD 11 C_EXTENSIONS OFF)
    if(CMAKE_CROSSCOMPILING AND TFIT_CORE STREQUAL "cortex-m7")
        set(board mps2-an500)
    elseif(CMAKE_CROSSCOMPILING)
        set(board mps2-an386)
    else()
        set(board native)
    endif()
    target_compile_definitions(${target} PRIVATE
        "GOLDEN_H=\"${name}_golden.h\""
        "GOLDEN_SETS=TFIT_${upper}_GOLDEN_SETS"
        "GOLDEN_Q31_SETS=TFIT_${upper}_GOLDEN_Q31_SETS"
        "TFIT_${upper}_IMPLEMENTATION"
        "LABEL=\"${PROJECT_NAME} ${name}/${board}\""
        $<$<BOOL:${ARG_PLANT}>:PLANT_MISMATCH>)
    if(CMAKE_CROSSCOMPILING)
        target_link_libraries(${target} PRIVATE tfit::startup tfit::semihost)
        target_link_options(${target} PRIVATE "-L${TFIT_LINKER_DIR}" "SHELL:-T ${board}.ld"
                            "-Wl,-Map=$<TARGET_FILE:${target}>.map")
        set_target_properties(${target} PROPERTIES SUFFIX .elf
            LINK_DEPENDS "${TFIT_LINKER_DIR}/${board}.ld;${TFIT_LINKER_DIR}/sections.ld")
    endif()
endfunction()
