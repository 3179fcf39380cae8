# Installation and the Debian package (deploy/package.sh builds it; docs/operations.md).
# An installed skyig finds its data at <bin>/../share/skyig (ephemeris/data_files.h), so the
# executable goes to bin/ and the data to share/skyig under the same prefix, whatever the
# prefix: these two destinations are fixed, not GNUInstallDirs' variables.
include(GNUInstallDirs)

install(TARGETS skyig RUNTIME DESTINATION bin COMPONENT skyig)
install(FILES ${SKYIG_DATA_FILES} DESTINATION share/skyig COMPONENT skyig)
# The service: its unit and its system user. deploy/skyig.service names the package's paths
# (/usr/bin/skyig, /etc/skyig/skyig.toml); the installed unit names those of the prefix it is
# installed under, chosen at install time (`cmake --install --prefix P`, the package's /usr),
# and the configuration directory below (absolute as the package sets it, else under P).
install(CODE "
  set(prefix \"\${CMAKE_INSTALL_PREFIX}\")
  if(IS_ABSOLUTE \"${CMAKE_INSTALL_SYSCONFDIR}\")
    set(sysconf \"${CMAKE_INSTALL_SYSCONFDIR}\")
  else()
    set(sysconf \"\${prefix}/${CMAKE_INSTALL_SYSCONFDIR}\")
  endif()
  file(READ \"${PROJECT_SOURCE_DIR}/deploy/skyig.service\" unit)
  string(REPLACE \"ExecStart=/usr/bin/skyig \" \"ExecStart=\${prefix}/bin/skyig \" unit \"\${unit}\")
  string(REPLACE \" --config /etc/skyig/skyig.toml \" \" --config \${sysconf}/skyig/skyig.toml \" unit \"\${unit}\")
  string(REPLACE \"file:///usr/share/doc/skyig/\" \"file://\${prefix}/share/doc/skyig/\" unit \"\${unit}\")
  set(path \"\$ENV{DESTDIR}\${prefix}/lib/systemd/system/skyig.service\")
  message(STATUS \"Installing: \${path} (ExecStart=\${prefix}/bin/skyig)\")
  file(WRITE \"\${path}\" \"\${unit}\")
  list(APPEND CMAKE_INSTALL_MANIFEST_FILES \"\${path}\")
" COMPONENT skyig)
install(FILES ${PROJECT_SOURCE_DIR}/deploy/skyig.sysusers DESTINATION lib/sysusers.d RENAME skyig.conf COMPONENT skyig)
# The example configuration becomes the node's: CMAKE_INSTALL_SYSCONFDIR is "etc" under the
# prefix by default (a test installs into a temporary prefix); deploy/package.sh sets it to
# /etc, where the package marks it a conffile (dpkg keeps the administrator's edits).
install(FILES ${PROJECT_SOURCE_DIR}/config/skyig.toml DESTINATION ${CMAKE_INSTALL_SYSCONFDIR}/skyig COMPONENT skyig)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/THIRD_PARTY_NOTICES.md
              ${PROJECT_SOURCE_DIR}/docs/operations.md
        DESTINATION share/doc/skyig COMPONENT skyig)
install(FILES ${PROJECT_SOURCE_DIR}/config/dome5.toml ${PROJECT_SOURCE_DIR}/config/circuit.csv
        DESTINATION share/doc/skyig/examples COMPONENT skyig)

# CPack: one .deb, its runtime dependencies found by dpkg-shlibdeps from the libraries the
# executable links (none of the build or test packages of deploy/setup.sh). Mesa's drivers are
# loaded by libEGL at run time, not linked, so they are named here: llvmpipe where there is no
# GPU (libgl1-mesa-dri) and the EGL vendor library (libegl-mesa0).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME skyig)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "skyig maintainers <skyig@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "sky image generator of a helicopter flight simulator (IG node)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "systemd")
# Maintainer scripts (create the user, enable the unit; see each file) and the conffile list.
if(IS_ABSOLUTE "${CMAKE_INSTALL_SYSCONFDIR}")
  set(SKYIG_PACKAGE_SYSCONFDIR "${CMAKE_INSTALL_SYSCONFDIR}")
else()
  set(SKYIG_PACKAGE_SYSCONFDIR "${CPACK_PACKAGING_INSTALL_PREFIX}/${CMAKE_INSTALL_SYSCONFDIR}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/deploy/debian/conffiles.in ${PROJECT_BINARY_DIR}/debian/conffiles @ONLY)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
    ${PROJECT_BINARY_DIR}/debian/conffiles
    ${PROJECT_SOURCE_DIR}/deploy/debian/postinst
    ${PROJECT_SOURCE_DIR}/deploy/debian/prerm
    ${PROJECT_SOURCE_DIR}/deploy/debian/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
