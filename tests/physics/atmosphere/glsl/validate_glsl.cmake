# Script mode: cmake -DSHADERS=<the source root> -DINPUT=<file> -DOUTPUT=<file> -DVALIDATOR=<exe>
#   -P validate_glsl.cmake
# Resolves `#include "path"` relative to the source root (as skyig's shader loader does), prepends
# `#version 450 core` and physics/common/glsl_prelude.glsl, and compiles the result with glslang.
function(resolve_includes file out_var depth)
  if(depth GREATER 16)
    message(FATAL_ERROR "include depth exceeded at ${file}")
  endif()
  # Whole-file string operations only: CMake lists would split GLSL lines at semicolons.
  file(READ "${file}" text)
  string(REGEX MATCHALL "#include[ \t]+\"[^\"]+\"" includes "${text}")
  foreach(directive IN LISTS includes)
    string(REGEX REPLACE "#include[ \t]+\"([^\"]+)\"" "\\1" name "${directive}")
    set(inc "${SHADERS}/${name}")
    if(NOT EXISTS "${inc}")
      message(FATAL_ERROR "${file}: cannot find include ${name}")
    endif()
    math(EXPR next "${depth} + 1")
    resolve_includes("${inc}" sub ${next})
    string(REPLACE "${directive}" "${sub}" text "${text}")
  endforeach()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

resolve_includes("${SHADERS}/physics/common/glsl_prelude.glsl" prelude 0)
resolve_includes("${INPUT}" body 0)
file(WRITE "${OUTPUT}" "#version 450 core\n${prelude}${body}")
execute_process(COMMAND "${VALIDATOR}" "${OUTPUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "glslang rejected ${OUTPUT}:\n${out}${err}")
endif()
message(STATUS "GLSL OK: ${INPUT}")
