# `cmake --install` of this build into PREFIX, then the installed skyig run as a node runs it:
# with SKYIG_DATA_DIR unset it reads PREFIX/share/skyig, its own prefix's data, and renders a
# frame from it; with that directory moved away it exits 2 naming it, so it read no other copy
# (the build tree's share/skyig, the sources). The service's files are where the package puts
# them, relative to the prefix.
#   cmake -DBINARY_DIR=... -DPREFIX=... -DWORK=... -P check_install.cmake
file(REMOVE_RECURSE ${PREFIX} ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${PREFIX} --strip
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BINARY_DIR} --prefix ${PREFIX} failed (${rc}):\n${out}${err}")
endif()
foreach(f bin/skyig share/skyig/bsc5.csv share/skyig/moon.png share/skyig/milkyway.png
          lib/systemd/system/skyig.service lib/sysusers.d/skyig.conf etc/skyig/skyig.toml)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "the install has no ${PREFIX}/${f}")
  endif()
endforeach()

set(skyig ${CMAKE_COMMAND} -E env --unset=SKYIG_DATA_DIR XDG_CACHE_HOME=${WORK}/cache ${PREFIX}/bin/skyig)
execute_process(COMMAND ${skyig} --version --caps RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(expected "Data files:    ${PREFIX}/share/skyig (beside the executable)\n")
string(FIND "${out}" "${expected}" at)
if(NOT rc EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "installed skyig --version --caps (${rc}) does not say \"${expected}\":\n${out}${err}")
endif()

set(render render --sky-model preetham --size 64x48 --png ${WORK}/sky.png)
execute_process(COMMAND ${skyig} ${render} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/sky.png)
  message(FATAL_ERROR "installed skyig render failed (${rc}):\n${out}${err}")
endif()

file(RENAME ${PREFIX}/share/skyig ${PREFIX}/share/skyig.away)
execute_process(COMMAND ${skyig} ${render} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(RENAME ${PREFIX}/share/skyig.away ${PREFIX}/share/skyig)
string(FIND "${err}" "${PREFIX}/share/skyig" named)
if(NOT rc EQUAL 2 OR named EQUAL -1)
  message(FATAL_ERROR "installed skyig without its share/skyig exited ${rc}, not 2 naming ${PREFIX}/share/skyig:\n${out}${err}")
endif()
message(STATUS "installed skyig reads ${PREFIX}/share/skyig and renders from it")
