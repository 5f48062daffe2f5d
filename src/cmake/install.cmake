# Install rules, the man page and the Debian package (issue #15).
#   cmake --install build [--prefix P]   bin/chainbreak, bin/chainbreak-view, the shared core
#                                        and the picture commands' module (lib[/<multiarch>]/
#                                        chainbreak/libchainbreak-core.so and
#                                        chainbreak-pictures.so, found by the programs relative
#                                        to themselves), the Python module
#                                        (lib/python3/dist-packages), share/chainbreak/scenes,
#                                        share/man/man1/chainbreak.1
#   cd build && cpack -G DEB             chainbreak_<version>_<arch>.deb, prefix /usr
include(GNUInstallDirs)

install(TARGETS chainbreak RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
# CHAINBREAK_LIB_INSTALL_DIR comes from src/cmake/core_library.cmake (which installs the core
# there); src/app/CMakeLists.txt builds the path from bin to it into the program.
install(TARGETS chainbreak_pictures LIBRARY DESTINATION ${CHAINBREAK_LIB_INSTALL_DIR}
        COMPONENT cli)
if(TARGET chainbreak-view)
  install(TARGETS chainbreak-view RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
  cb_install_rpath(chainbreak-view ${CMAKE_INSTALL_BINDIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/chainbreak/scenes
        COMPONENT cli)

# The man page is made at build time from the help text the built program prints
# (src/cmake/manpage.cmake runs `chainbreak --help` and each command's --help), so the two cannot
# drift apart.
set(CHAINBREAK_MANPAGE ${PROJECT_BINARY_DIR}/man/chainbreak.1)
add_custom_command(
  OUTPUT ${CHAINBREAK_MANPAGE}
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:chainbreak> -DOUT=${CHAINBREAK_MANPAGE}
          -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/src/cmake/manpage.cmake
  DEPENDS chainbreak ${PROJECT_SOURCE_DIR}/src/cmake/manpage.cmake
  COMMENT "Man page chainbreak.1 from chainbreak --help")
add_custom_target(chainbreak_manpage ALL DEPENDS ${CHAINBREAK_MANPAGE})
install(FILES ${CHAINBREAK_MANPAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT cli)

# CPack: one .deb with everything above. Depends: the shared libraries the binaries and the
# picture module link, found by dpkg-shlibdeps (libavcodec59, libc6, ...), plus what is opened at run time and so
# invisible to it: Mesa's OSMesa and EGL (dlopen, src/gl), the DejaVu fonts, and numpy for the
# Python module.
set(CPACK_PACKAGE_NAME chainbreak)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "chainbreak maintainers <chainbreak@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "which part of a harmonic chain breaks: simulator, renderer")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libosmesa6, libegl1, libegl-mesa0, fonts-dejavu-core, python3, python3-numpy")
include(CPack)
