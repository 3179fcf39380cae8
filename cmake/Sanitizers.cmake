# SKYIG_SANITIZE: sanitizers for every target of the build, compile and link, as a list:
#   -DSKYIG_SANITIZE=address,undefined   ASan + UBSan (CI: deploy/test-sanitize.sh)
#   -DSKYIG_SANITIZE=thread              TSan, for the node's threads (docs/design.md, "Build habits")
# With -fno-omit-frame-pointer for whole stacks, and -fno-sanitize-recover=undefined so that a
# finding fails the test rather than printing a line nobody reads. Every program (skyig, the
# tests) links skyig_sanitizer_defaults: the options and the third-party suppressions of
# tests/sanitizers/, compiled in so that ctest, a test's child skyig and a hand-run program all
# use them. The fuzz targets keep their own flags (tests/fuzz).
set(SKYIG_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined or thread")
string(REPLACE "," ";" SKYIG_SANITIZERS "${SKYIG_SANITIZE}")

# skyig_sanitizer_defaults(TARGET [NO_EXIT_LEAK_CHECK]): TARGET (an executable) runs with the
# defaults; nothing without SKYIG_SANITIZE. NO_EXIT_LEAK_CHECK: the skyig program's (see
# tests/sanitizers/sanitizer_defaults.cpp.in).
function(skyig_sanitizer_defaults target)
  if(NOT TARGET skyig_sanitizer_defaults)
    return()
  endif()
  if("${ARGN}" STREQUAL "NO_EXIT_LEAK_CHECK")
    target_link_libraries(${target} PRIVATE skyig_sanitizer_defaults_no_exit_leak_check)
  else()
    target_link_libraries(${target} PRIVATE skyig_sanitizer_defaults)
  endif()
endfunction()

if(NOT SKYIG_SANITIZERS)
  return()
endif()

set(known address undefined thread leak)
foreach(s IN LISTS SKYIG_SANITIZERS)
  if(NOT s IN_LIST known)
    message(FATAL_ERROR "SKYIG_SANITIZE: unknown sanitizer '${s}' (one of: ${known})")
  endif()
endforeach()
if("thread" IN_LIST SKYIG_SANITIZERS AND ("address" IN_LIST SKYIG_SANITIZERS OR "leak" IN_LIST SKYIG_SANITIZERS))
  message(FATAL_ERROR "SKYIG_SANITIZE: thread does not combine with address or leak; use a second build directory")
endif()
list(JOIN SKYIG_SANITIZERS "," joined)
message(STATUS "Sanitizers: ${joined}")
add_compile_options(-fsanitize=${joined} -fno-omit-frame-pointer)
add_link_options(-fsanitize=${joined})
if("undefined" IN_LIST SKYIG_SANITIZERS)
  add_compile_options(-fno-sanitize-recover=undefined)
endif()
# GCC 12 sees uninitialised members in instrumented libstdc++ (std::regex's states, through
# render/gl/shader_source.cpp) that are not there; the plain build keeps the warning.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-maybe-uninitialized)
endif()

set(dir ${PROJECT_SOURCE_DIR}/tests/sanitizers)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${dir}/lsan.supp ${dir}/tsan.supp)
file(READ ${dir}/lsan.supp SKYIG_LSAN_SUPPRESSIONS)
file(READ ${dir}/tsan.supp SKYIG_TSAN_SUPPRESSIONS)
configure_file(${dir}/sanitizer_defaults.cpp.in ${PROJECT_BINARY_DIR}/sanitizer_defaults.cpp @ONLY)
add_library(skyig_sanitizer_defaults OBJECT ${PROJECT_BINARY_DIR}/sanitizer_defaults.cpp)
add_library(skyig_sanitizer_defaults_no_exit_leak_check OBJECT ${PROJECT_BINARY_DIR}/sanitizer_defaults.cpp)
target_compile_definitions(skyig_sanitizer_defaults_no_exit_leak_check PRIVATE SKYIG_NO_EXIT_LEAK_CHECK)
