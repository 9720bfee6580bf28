# What `cmake --install` puts where (GNU layout under CMAKE_INSTALL_PREFIX,
# /usr/local by default, /usr in the Debian packages) and the two Debian
# packages CPack builds from it (`cpack -G DEB` in the build directory):
#
#   regio-solve  bin/regio-solve, share/regio/ (sample scenes, the JSON
#                Schema, the batch scripts for Slurm and ssh), the docs
#                in share/doc/regio-solve.
#                No Qt: what a batch machine installs.
#   regio        bin/regio, its desktop entry and icon; depends on
#                regio-solve (the samples, the batch command it exports for).
#
# The editor's translations are compiled into it (qt_add_translations), and
# an installed editor finds the samples in ../share/regio/scenes.
include(GNUInstallDirs)

install(TARGETS regio-solve RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT solve)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/scenes ${PROJECT_SOURCE_DIR}/resources/schema
  DESTINATION ${CMAKE_INSTALL_DATADIR}/regio COMPONENT solve)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/slurm/submit.sh ${PROJECT_SOURCE_DIR}/tools/slurm/regio-array.sbatch
  ${PROJECT_SOURCE_DIR}/tools/slurm/regio-summary.sbatch
  DESTINATION ${CMAKE_INSTALL_DATADIR}/regio/tools/slurm COMPONENT solve)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/ssh/solve-over-ssh.sh
  DESTINATION ${CMAKE_INSTALL_DATADIR}/regio/tools/ssh COMPONENT solve)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/regio-solve COMPONENT solve)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/regio-solve COMPONENT solve)

if(REGIO_BUILD_EDITOR)
  # Everything of ours is linked in statically: no run path to set (Qt's
  # project setup asks for $ORIGIN/../lib, which an ELF file without one
  # cannot take).
  set_target_properties(regio PROPERTIES INSTALL_RPATH "")
  install(TARGETS regio RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT editor)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/regio.desktop
    DESTINATION ${CMAKE_INSTALL_DATADIR}/applications COMPONENT editor)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/regio.svg
    DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps COMPONENT editor)
endif()

set(CPACK_PACKAGE_NAME regio)
set(CPACK_PACKAGE_VENDOR "Regio")
set(CPACK_PACKAGE_CONTACT "Regio developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "radiosity scene editor and solver with regional BSP trees")
set(CPACK_PACKAGE_INSTALL_DIRECTORY regio)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
set(CPACK_DEBIAN_SOLVE_PACKAGE_NAME regio-solve)
set(CPACK_DEBIAN_SOLVE_PACKAGE_SECTION science)
set(CPACK_COMPONENT_SOLVE_DESCRIPTION
  "radiosity solver for Regio scenes, headless (no Qt)\n regio-solve checks, solves, imports and sweeps Regio scenes, one or a batch\n of many, with the paper's regional BSP trees and progressive shooting. With\n the sample scenes, the scene schema and the scripts that run batches on a\n Slurm cluster or over ssh.")
set(CPACK_DEBIAN_EDITOR_PACKAGE_NAME regio)
set(CPACK_DEBIAN_EDITOR_PACKAGE_DEPENDS "regio-solve (= ${PROJECT_VERSION})")
# Qt's own strings (dialog buttons) in the user's language.
set(CPACK_DEBIAN_EDITOR_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_COMPONENT_EDITOR_DESCRIPTION
  "radiosity scene editor with regions and BSP orders\n Regio builds scenes of whole-part B-rep objects, axis-aligned regions and\n their BSP root-patch orders, and previews their radiosity as it converges.")
set(CPACK_COMPONENTS_ALL solve)
if(REGIO_BUILD_EDITOR)
  list(APPEND CPACK_COMPONENTS_ALL editor)
endif()
include(CPack)
