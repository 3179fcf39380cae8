# The data files skyig reads at run time (ephemeris/data_files.h), staged in the build tree as an
# installed node has them: build/share/skyig beside build/bin/skyig, which finds them at
# <executable's directory>/../share/skyig. No path of the source tree is compiled in.
# Target skyig_data copies them at build time, so an edited file reaches the next run; the
# executable and the test programs depend on it.
set(SKYIG_DATA_FILES
  ${PROJECT_SOURCE_DIR}/ephemeris/data/bsc5.csv
  ${PROJECT_SOURCE_DIR}/physics/moon/data/moon.png
  ${PROJECT_SOURCE_DIR}/physics/night/data/milkyway.png)
set(SKYIG_STAGED_DATA_DIR ${PROJECT_BINARY_DIR}/share/skyig)

set(staged)
foreach(f IN LISTS SKYIG_DATA_FILES)
  get_filename_component(name ${f} NAME)
  add_custom_command(
    OUTPUT ${SKYIG_STAGED_DATA_DIR}/${name}
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${f} ${SKYIG_STAGED_DATA_DIR}/${name}
    DEPENDS ${f}
    COMMENT "Staging ${name} in share/skyig"
    VERBATIM)
  list(APPEND staged ${SKYIG_STAGED_DATA_DIR}/${name})
endforeach()
add_custom_target(skyig_data ALL DEPENDS ${staged})
