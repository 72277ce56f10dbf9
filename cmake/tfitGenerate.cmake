# tfitGenerate.cmake — regenerate a tissuefit header at build time.
#
#   tfit_generate_header(NAME name SCENE scene.yaml OUTPUT_DIR dir
#                        [TARGET tgt] [TOOL path] [OPTIONS --set k=v ...])
#
# adds a build rule that runs `tissuefit fit SCENE -o OUTPUT_DIR/NAME.h
# OPTIONS...` whenever the scene (or the tool) changes; it writes NAME.h and
# NAME_golden.h (docs/header-format.md §1).  Sets NAME_TFIT_HEADER and
# NAME_TFIT_GOLDEN in the caller's scope, and creates the target
# tfit_generate_NAME.  With TARGET, tgt gets OUTPUT_DIR as an include
# directory and builds after the header is written.
#
# The tool: TOOL, else the installed tfit::tissuefit (find_package(tfit)),
# else `tissuefit` on the PATH.  It runs on the build machine, whatever the
# target (cross builds included).
function(tfit_generate_header)
    cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME;SCENE;OUTPUT_DIR;TARGET;TOOL" "OPTIONS")
    foreach(_req IN ITEMS NAME SCENE OUTPUT_DIR)
        if(NOT ARG_${_req})
            message(FATAL_ERROR "tfit_generate_header: ${_req} is required")
        endif()
    endforeach()
    if(ARG_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "tfit_generate_header: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
    endif()
    # The tool refuses other names (a lower-case C identifier, docs/header-format.md §1).
    if(NOT ARG_NAME MATCHES "^[a-z_][a-z0-9_]*$")
        message(FATAL_ERROR "tfit_generate_header: NAME '${ARG_NAME}' is not a lower-case C identifier")
    endif()

    if(ARG_TOOL)
        set(_tool "${ARG_TOOL}")
        set(_tool_dep "${ARG_TOOL}")
    elseif(TARGET tfit::tissuefit)
        set(_tool tfit::tissuefit)
        set(_tool_dep "$<TARGET_FILE:tfit::tissuefit>")
    else()
        find_program(TFIT_TISSUEFIT tissuefit)
        if(NOT TFIT_TISSUEFIT)
            message(FATAL_ERROR "tfit_generate_header: no tissuefit tool (pass TOOL, or install tissuefit)")
        endif()
        set(_tool "${TFIT_TISSUEFIT}")
        set(_tool_dep "${TFIT_TISSUEFIT}")
    endif()

    get_filename_component(_scene "${ARG_SCENE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(_dir "${ARG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    set(_header "${_dir}/${ARG_NAME}.h")
    set(_golden "${_dir}/${ARG_NAME}_golden.h")
    file(MAKE_DIRECTORY "${_dir}")
    add_custom_command(
        OUTPUT "${_header}" "${_golden}"
        COMMAND ${_tool} fit "${_scene}" -o "${_header}" ${ARG_OPTIONS}
        DEPENDS "${_scene}" "${_tool_dep}"
        COMMENT "tissuefit fit ${ARG_SCENE} -> ${ARG_NAME}.h"
        VERBATIM)
    add_custom_target(tfit_generate_${ARG_NAME} DEPENDS "${_header}" "${_golden}")
    if(ARG_TARGET)
        add_dependencies(${ARG_TARGET} tfit_generate_${ARG_NAME})
        target_include_directories(${ARG_TARGET} PRIVATE "${_dir}")
    endif()
    set(${ARG_NAME}_TFIT_HEADER "${_header}" PARENT_SCOPE)
    set(${ARG_NAME}_TFIT_GOLDEN "${_golden}" PARENT_SCOPE)
endfunction()
