# Installation (GNUInstallDirs) and the Debian package (cpack -G DEB). The desktop entry, the
# icons, the metainfo and the scenes are installed by resources/CMakeLists.txt.
install(TARGETS chaplygin-lab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# the man page, written from --help at install time (its FILES section names the prefix being
# installed to, /usr in the Debian package), and the Debian changelog, both compressed as Debian's
# policy asks (gzip -n: no name or time stamp, so the package is reproducible)
find_program(CHAPLYGIN_GZIP gzip REQUIRED)
set(man_page ${PROJECT_BINARY_DIR}/man/chaplygin-lab.1)
install(CODE "
  execute_process(COMMAND \${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:chaplygin-lab>
      -DOUTPUT=${man_page} -DVERSION=${PROJECT_VERSION} -DPREFIX=\${CMAKE_INSTALL_PREFIX}
      -DDATADIR=${CMAKE_INSTALL_DATADIR} -DDOCDIR=${CMAKE_INSTALL_DOCDIR}
      -P ${PROJECT_SOURCE_DIR}/scripts/cmake/man_page.cmake
    COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND ${CHAPLYGIN_GZIP} -9nf ${man_page} COMMAND_ERROR_IS_FATAL ANY)")
install(FILES ${man_page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
set(changelog ${PROJECT_BINARY_DIR}/debian/changelog.gz)
add_custom_command(OUTPUT ${changelog}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/debian
  COMMAND ${CHAPLYGIN_GZIP} -9nc ${PROJECT_SOURCE_DIR}/resources/debian/changelog > ${changelog}
  DEPENDS ${PROJECT_SOURCE_DIR}/resources/debian/changelog
  COMMENT "Compressing the Debian changelog")
add_custom_target(chaplygin_changelog ALL DEPENDS ${changelog})
install(FILES ${changelog} resources/debian/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(FILES README.md docs/architecture.md docs/numerics.md docs/physics.md docs/robustness.md
              docs/user-guide.md docs/python.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/images DESTINATION ${CMAKE_INSTALL_DOCDIR})
if(CHAPLYGIN_PYTHON)
  install(FILES docs/notebooks/tour.ipynb DESTINATION ${CMAKE_INSTALL_DOCDIR}/notebooks)
endif()

set(CPACK_PACKAGE_NAME chaplygin-lab)
set(CPACK_PACKAGE_VENDOR "The Chaplygin Lab maintainers")
set(CPACK_PACKAGE_CONTACT "The Chaplygin Lab maintainers <maintainers@chaplyginlab.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Steer nonholonomic Chaplygin systems along a path")
# the control file's long description, below the summary that CPack puts first: lines of at most
# 80 characters (lintian), indented by CPack
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "A teaching laboratory for nonholonomic mechanics: a Chaplygin sleigh, a rolling
disk or a two-wheeled carriage follows a typed or drawn path under a tracking
control, beside the free and the vakonomic motion, with live plots, a
presentation mode for the lecture hall, a gallery of failing numerical methods
and a headless command line that writes CSV, JSON, figures and animations.")
set(CPACK_PACKAGE_DESCRIPTION "${CPACK_DEBIAN_PACKAGE_DESCRIPTION}")
set(CPACK_PACKAGE_HOMEPAGE_URL "https://github.com/chaplyginlab/chaplygin-lab")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Depends from the libraries the program links (Qt 6, GSL, muparser, GiNaC), via dpkg-shlibdeps
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# the Python module (app/python/CMakeLists.txt) is an extension of the python3 it was built for: that
# minor version, and NumPy for its arrays (Debian's python policy for extension modules)
if(CHAPLYGIN_PYTHON)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${CHAPLYGIN_PYTHON_VERSION}~), \
python3 (<< ${CHAPLYGIN_PYTHON_NEXT_VERSION}), python3-numpy")
endif()
# GIF and MP4 export run the ffmpeg program; Qt's own catalogues translate the dialogs' buttons
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg, qt6-translations-l10n")
set(CPACK_STRIP_FILES ON)
include(CPack)
