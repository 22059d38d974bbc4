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
# The molecule headers of the public API; the others (report JSON, batch
# tables, viewer scripts) are the CLI's and stay in the tree.
set(public_molecule_headers
    analysis atom_balls cavities ligandability_model mesh_export output_selection pocket_meshes pocket_search radii
    radius_file
    site_features structure surface tunnel_paths tunnel_start)
list(TRANSFORM public_molecule_headers PREPEND ${PROJECT_SOURCE_DIR}/molecule/include/molecule/)
list(TRANSFORM public_molecule_headers APPEND .hpp)
install(FILES ${public_molecule_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/molecule)

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
