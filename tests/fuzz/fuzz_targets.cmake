# The libFuzzer targets; needs a clang compiler, SKYIG_ROOT (the repository root) and the
# skyig_warnings target. Included by tests/fuzz/CMakeLists.txt in a clang build, and by the
# clang sub-build (tests/fuzz/standalone) of a gcc build.
include(${CMAKE_CURRENT_LIST_DIR}/target_list.cmake)
set(fuzz_flags -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined)

include(${SKYIG_ROOT}/protocol/sources.cmake)
list(TRANSFORM SKYIG_PROTOCOL_SOURCES PREPEND "${SKYIG_ROOT}/protocol/")
# The protocol sources again, instrumented for coverage and the sanitizers.
add_library(skyig_protocol_fuzz STATIC ${SKYIG_PROTOCOL_SOURCES})
target_include_directories(skyig_protocol_fuzz PUBLIC ${SKYIG_ROOT})
target_compile_options(skyig_protocol_fuzz PRIVATE ${fuzz_flags})
target_link_libraries(skyig_protocol_fuzz PRIVATE skyig_warnings)

foreach(target ${SKYIG_FUZZ_TARGETS})
  add_executable(${target} ${CMAKE_CURRENT_LIST_DIR}/${target}.cpp)
  target_compile_options(${target} PRIVATE ${fuzz_flags})
  target_link_options(${target} PRIVATE -fsanitize=fuzzer,address,undefined)
  target_link_libraries(${target} PRIVATE skyig_protocol_fuzz skyig_warnings)
endforeach()
