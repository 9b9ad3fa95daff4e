# cmake --install: headers, the layer libraries with their CMake targets (dymesh::core, ::accel,
# ::analysis, ::io, ::report, ::c), the package configuration and version, and dymesh.pc
include(CMakePackageConfigHelpers)
set(DYMESH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dymesh)
install(TARGETS dymesh_core dymesh_accel dymesh_analysis dymesh_io dymesh_report dymesh_ensemble ${DYMESH_C_TARGET}
        EXPORT dymeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(layer core accel analysis io report ensemble api)
  if(EXISTS ${PROJECT_SOURCE_DIR}/${layer}/include)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
if(TARGET dymesh)
  install(TARGETS dymesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT dymeshTargets NAMESPACE dymesh:: DESTINATION ${DYMESH_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/dymeshConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/dymeshConfig.cmake INSTALL_DESTINATION ${DYMESH_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/dymeshConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/dymeshConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/dymeshConfigVersion.cmake
        DESTINATION ${DYMESH_CMAKE_DIR})
# relocatable: the prefix is found from the .pc file's own folder, wherever the prefix is installed
file(RELATIVE_PATH DYMESH_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
configure_file(${CMAKE_CURRENT_LIST_DIR}/dymesh.pc.in ${CMAKE_CURRENT_BINARY_DIR}/dymesh.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/dymesh.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
