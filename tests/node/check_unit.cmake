# The systemd unit as the package installs it (PREFIX = ROOT/usr, from Binary.Install), checked by
# systemd-analyze in ROOT, a copy of this machine's system units with skyig enabled as its
# [Install] section says:
#   - `verify skyig.service graphical.target` passes: the unit loads, ExecStart's binary exists,
#     and the boot transaction has no ordering cycle (After=graphical.target with
#     WantedBy=multi-user.target had one: the check first shows it sees such a cycle);
#   - `security --offline=yes` rates it at most THRESHOLD tenths (docs/operations.md).
#   cmake -DSYSTEMD_ANALYZE=... -DROOT=... -DTHRESHOLD=... -P check_unit.cmake
set(units ${ROOT}/usr/lib/systemd/system)
set(unit ${units}/skyig.service)
if(NOT EXISTS ${unit})
  message(FATAL_ERROR "no installed unit ${unit}")
endif()
# This machine's units (cp: their names hold systemd's escapes, e.g. "\x2d"), then the
# installed unit again over any skyig.service of this machine.
file(READ ${unit} text)
foreach(host /usr/lib/systemd/system /lib/systemd/system)
  if(EXISTS ${host}/multi-user.target)
    execute_process(COMMAND cp -a ${host}/. ${units}/ RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "cannot copy ${host} into ${units}: ${err}")
    endif()
    break()
  endif()
endforeach()
file(WRITE ${unit} "${text}")
if(NOT EXISTS ${units}/graphical.target)
  message(FATAL_ERROR "no system units of this machine found to verify against (graphical.target)")
endif()

# Enables NAME as `systemctl enable` does: a link in each WantedBy= target's .wants.
function(enable name text)
  string(REGEX MATCHALL "\nWantedBy=[^\n]*" lines "${text}")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "\nWantedBy=" "" targets "${line}")
    separate_arguments(targets)
    foreach(t IN LISTS targets)
      file(MAKE_DIRECTORY ${ROOT}/etc/systemd/system/${t}.wants)
      file(CREATE_LINK /usr/lib/systemd/system/${name} ${ROOT}/etc/systemd/system/${t}.wants/${name} SYMBOLIC)
    endforeach()
  endforeach()
endfunction()

function(verify name result output)
  execute_process(COMMAND ${SYSTEMD_ANALYZE} verify --root=${ROOT} ${name} graphical.target
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${result} ${rc} PARENT_SCOPE)
  set(${output} "${out}${err}" PARENT_SCOPE)
endfunction()

# The control: the old unit's ordering, After=graphical.target, must be reported as a cycle.
string(REPLACE "[Unit]\n" "[Unit]\nAfter=graphical.target\n" cyclic "${text}")
file(WRITE ${units}/skyig-cycle.service "${cyclic}")
enable(skyig-cycle.service "${cyclic}")
verify(skyig-cycle.service rc out)
file(REMOVE ${units}/skyig-cycle.service)
file(GLOB links ${ROOT}/etc/systemd/system/*.wants/skyig-cycle.service)
if(links)
  file(REMOVE ${links})
endif()
if(rc EQUAL 0 OR NOT out MATCHES "cycl")
  message(FATAL_ERROR "systemd-analyze verify did not report the ordering cycle of After=graphical.target (${rc}):\n${out}")
endif()

enable(skyig.service "${text}")
verify(skyig.service rc out)
if(NOT rc EQUAL 0 OR out MATCHES "(^|\n)skyig")
  message(FATAL_ERROR "systemd-analyze verify --root=${ROOT} skyig.service failed (${rc}):\n${out}")
endif()

execute_process(COMMAND ${SYSTEMD_ANALYZE} security --offline=yes --threshold=${THRESHOLD} --no-pager ${unit}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCH "Overall exposure level[^\n]*" score "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "systemd-analyze security rates the unit over ${THRESHOLD} tenths: ${score}\n${out}${err}")
endif()
message(STATUS "skyig.service verifies; ${score}")
