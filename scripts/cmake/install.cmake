# Installation (GNUInstallDirs) and the Debian package (cpack -G DEB). The desktop entry, the
# icons, the metainfo and the scenes are installed by resources/CMakeLists.txt.
install(TARGETS chaplygin-lab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(man_page ${PROJECT_BINARY_DIR}/man/chaplygin-lab.1)
add_custom_command(OUTPUT ${man_page}
  COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0
          ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:chaplygin-lab> -DOUTPUT=${man_page}
          -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/scripts/cmake/man_page.cmake
  DEPENDS chaplygin-lab ${PROJECT_SOURCE_DIR}/scripts/cmake/man_page.cmake
  COMMENT "Writing the man page from --help"
  VERBATIM)
add_custom_target(chaplygin_man_page ALL DEPENDS ${man_page})
install(FILES ${man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

install(FILES README.md COPYING docs/architecture.md docs/numerics.md docs/physics.md docs/robustness.md
              docs/user-guide.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/images DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_PACKAGE_NAME chaplygin-lab)
set(CPACK_PACKAGE_VENDOR "The Chaplygin Lab maintainers")
set(CPACK_PACKAGE_CONTACT "The Chaplygin Lab maintainers <maintainers@chaplyginlab.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Steer nonholonomic Chaplygin systems along a path")
set(CPACK_PACKAGE_DESCRIPTION "A teaching laboratory for nonholonomic mechanics: a Chaplygin \
sleigh, a rolling disk or a two-wheeled carriage follows a typed or drawn path under a tracking \
control, with live plots, a gallery of failing methods and a headless command line.")
set(CPACK_PACKAGE_HOMEPAGE_URL "https://github.com/chaplyginlab/chaplygin-lab")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Depends from the libraries the program links (Qt 6, GSL, muparser, GiNaC), via dpkg-shlibdeps
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
