# `cmake --install` of this build as the package installs it (prefix /usr, under DESTDIR=ROOT),
# then the installed skyig run as a node runs it: with SKYIG_DATA_DIR unset it reads
# ROOT/usr/share/skyig, its own prefix's data, and renders a frame from it; with that directory
# moved away it exits 2 naming it, so it read no other copy (the build tree's share/skyig, the
# sources). The service's files are where the package puts them, and a unit installed under
# another prefix starts that prefix's skyig with that prefix's configuration.
#   cmake -DBINARY_DIR=... -DROOT=... -DWORK=... -P check_install.cmake
set(PREFIX ${ROOT}/usr)
file(REMOVE_RECURSE ${ROOT} ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -E env DESTDIR=${ROOT} ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix /usr --strip
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "DESTDIR=${ROOT} cmake --install ${BINARY_DIR} --prefix /usr failed (${rc}):\n${out}${err}")
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

# The unit's paths follow the prefix: /usr for the package, P for `--prefix P`.
function(expect_unit unit_file prefix)
  file(STRINGS ${unit_file} exec REGEX "^ExecStart=")
  set(want "ExecStart=${prefix}/bin/skyig serve --config ${prefix}/etc/skyig/skyig.toml ")
  string(FIND "${exec}" "${want}" at)
  if(NOT at EQUAL 0)
    message(FATAL_ERROR "${unit_file} says\n  ${exec}\nnot\n  ${want}...")
  endif()
endfunction()
expect_unit(${PREFIX}/lib/systemd/system/skyig.service /usr)
set(other ${WORK}/opt-skyig)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${other} --component skyig
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BINARY_DIR} --prefix ${other} failed (${rc}):\n${out}${err}")
endif()
expect_unit(${other}/lib/systemd/system/skyig.service ${other})
if(NOT EXISTS ${other}/bin/skyig OR NOT EXISTS ${other}/etc/skyig/skyig.toml)
  message(FATAL_ERROR "the unit under ${other} names files the install did not put there")
endif()
message(STATUS "the unit starts its own prefix's skyig with its configuration (/usr and ${other})")
