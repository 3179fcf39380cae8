# The skyig executable carries no path of the source or build tree in its constant data: data
# files are found at run time (ephemeris/data_files.h), never through a compiled-in path. Debug
# information names source files legitimately, so only the sections the program itself reads
# are searched: .rodata (string literals) and .data. Fails, naming the strings, when one holds
# SOURCE_DIR or BINARY_DIR.
#   cmake -DEXE=... -DOBJCOPY=... -DSOURCE_DIR=... -DBINARY_DIR=... -DWORK=... -P check_no_source_paths.cmake
file(MAKE_DIRECTORY ${WORK})
set(found)
set(markers)
foreach(section .rodata .data)
  set(dump ${WORK}/skyig${section}.bin)
  file(REMOVE ${dump})
  execute_process(COMMAND ${OBJCOPY} -O binary --only-section=${section} ${EXE} ${dump}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${dump})
    message(FATAL_ERROR "${OBJCOPY} could not extract ${section} of ${EXE}: ${err}")
  endif()
  foreach(dir IN ITEMS "${SOURCE_DIR}" "${BINARY_DIR}")
    string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" pattern "${dir}")
    file(STRINGS ${dump} hits REGEX "${pattern}")
    list(APPEND found ${hits})
  endforeach()
  file(STRINGS ${dump} hits REGEX "SKYIG_DATA_DIR")
  list(APPEND markers ${hits})
endforeach()

# The search must see the program's strings, or it proves nothing.
if(NOT markers)
  message(FATAL_ERROR "no string \"SKYIG_DATA_DIR\" found in ${EXE}'s .rodata: the check reads the wrong sections")
endif()
if(found)
  list(REMOVE_DUPLICATES found)
  list(JOIN found "\n  " lines)
  message(FATAL_ERROR "${EXE} has paths of the source or build tree compiled in:\n  ${lines}")
endif()
message(STATUS "no path of ${SOURCE_DIR} or ${BINARY_DIR} in ${EXE}'s .rodata and .data")
