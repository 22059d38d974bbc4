# SPDX-License-Identifier: Apache-2.0
# install(): the static libraries, their public headers (no GMP, nlohmann,
# OpenMesh or gemmi inside: checked by the test package.find_package), the
# CMake package alphapocketConfig.cmake with its version file, a pkg-config
# file, and the alphapocket binary.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(alpha PROPERTIES OUTPUT_NAME alphapocket_alpha EXPORT_NAME alpha)
set_target_properties(molecule PROPERTIES OUTPUT_NAME alphapocket_molecule EXPORT_NAME molecule)
install(TARGETS alpha molecule EXPORT alphapocketTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS alphapocket RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY libalpha/include/alpha DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/generated/alphapocket/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/alphapocket)
# The molecule headers of the public API are the folder include/molecule;
# the others (report JSON, batch tables, viewer scripts) sit next to their
# sources in molecule/src/<stage>/ and are the CLI's.
install(DIRECTORY molecule/include/molecule DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/alphapocket)
install(EXPORT alphapocketTargets NAMESPACE alphapocket:: DESTINATION ${config_dir})
configure_package_config_file(cmake/alphapocketConfig.cmake.in ${PROJECT_BINARY_DIR}/alphapocketConfig.cmake
                              INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/alphapocketConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/alphapocketConfig.cmake ${PROJECT_BINARY_DIR}/alphapocketConfigVersion.cmake
        DESTINATION ${config_dir})
# Relocatable: the prefix is found from the .pc file's own directory.
file(RELATIVE_PATH pc_prefix /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(cmake/alphapocket.pc.in ${PROJECT_BINARY_DIR}/alphapocket.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/alphapocket.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# report.html's viewer (molecule/report_assets.hpp looks for it in
# ../share/alphapocket/viewer from the executable): Mol* from npm (`npm ci
# --prefix report_assets`; OPTIONAL: without it pockets leaves report.html
# out with a warning). The pages' own scripts are compiled in.
install(FILES ${PROJECT_SOURCE_DIR}/report_assets/node_modules/molstar/build/viewer/molstar.js
              ${PROJECT_SOURCE_DIR}/report_assets/node_modules/molstar/build/viewer/molstar.css
        DESTINATION ${CMAKE_INSTALL_DATADIR}/alphapocket/viewer OPTIONAL)
