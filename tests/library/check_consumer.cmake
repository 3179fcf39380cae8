# tests/library/consumer built against the skyig installed in PREFIX, once with find_package
# (CMAKE_PREFIX_PATH only) and once with pkg-config's flags, each run with SKYIG_DATA_DIR unset
# (the library finds PREFIX/share/skyig beside itself) and a sane light checked.
#   cmake -DPREFIX=... -DSOURCE=... -DWORK=... -DCXX=... -DGENERATOR=... -DCACHE=... -P check_consumer.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/build -G ${GENERATOR}
                        -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer with find_package(skyig) failed (${rc}):\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer against skyig::skyig failed (${rc}):\n${out}${err}")
endif()

# pkg-config: the flags of PREFIX's skyig.pc, the library found at run time by its rpath.
file(GLOB_RECURSE pc ${PREFIX}/*/pkgconfig/skyig.pc)
if(NOT pc)
  message(FATAL_ERROR "no skyig.pc under ${PREFIX}")
endif()
get_filename_component(pcdir ${pc} DIRECTORY)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pcdir} pkg-config --cflags --libs skyig
                RESULT_VARIABLE rc OUTPUT_VARIABLE flags ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs skyig failed (${rc}): ${err}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
string(REGEX MATCH "-L[^;]+" libdir "${flags}")
string(SUBSTRING "${libdir}" 2 -1 libdir)
execute_process(COMMAND ${CXX} -std=c++17 ${SOURCE}/consumer.cpp ${flags} -Wl,-rpath,${libdir} -o ${WORK}/consumer_pc
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer with pkg-config's flags (${flags}) failed (${rc}):\n${out}${err}")
endif()

foreach(program ${WORK}/build/consumer ${WORK}/consumer_pc)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SKYIG_DATA_DIR XDG_CACHE_HOME=${CACHE} ${program}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${program} failed (${rc}):\n${out}${err}")
  endif()
  # Midsummer 13:00 CEST at 47 deg north: the sun 66 deg up, 80-120 klx of it on the ground,
  # a clear sky's ambient of 5-20 klx, and 20 km of clear air passing most of the green.
  foreach(check "sun_up=0\\.9" "sun_horizontal_lux=(8[0-9]|9[0-9]|1[01][0-9])[0-9][0-9][0-9]\n"
                "ambient_lux=([5-9]|1[0-9])[0-9][0-9][0-9](\\.[0-9]*)?\n" "transmittance_20km_green=0\\.[5-9]" "api=1")
    if(NOT out MATCHES "${check}")
      message(FATAL_ERROR "${program}: output does not match ${check}:\n${out}${err}")
    endif()
  endforeach()
endforeach()
message(STATUS "the consumer built with find_package(skyig) and with pkg-config, and ran:\n${out}")
