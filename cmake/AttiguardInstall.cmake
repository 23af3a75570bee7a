# Install rules (included at the end of src/CMakeLists.txt, docs/install.md): the libraries and
# their headers (with the generated attiguard/core/version.hpp), the command-line program, the
# CMake package lib/cmake/attiguard (attiguardConfig.cmake, attiguardConfigVersion.cmake,
# attiguardTargets.cmake, FindCSDP.cmake) exporting attiguard::flight and attiguard::attiguard,
# and the pkg-config files attiguard-flight.pc and attiguard.pc.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(ATTIGUARD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/attiguard)
set(attiguard_libraries attiguard_flight)
if(TARGET attiguard_core)
  list(APPEND attiguard_libraries attiguard_core)
endif()

install(TARGETS ${attiguard_libraries} EXPORT attiguardTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILE_SET generated_headers DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET attiguard)
  install(TARGETS attiguard RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT attiguardTargets NAMESPACE attiguard:: DESTINATION ${ATTIGUARD_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/attiguardConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/attiguardConfig.cmake
  INSTALL_DESTINATION ${ATTIGUARD_INSTALL_CMAKEDIR})
# 0.x releases are compatible only within the same minor version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/attiguardConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
set(attiguard_package_files ${PROJECT_BINARY_DIR}/cmake/attiguardConfig.cmake
                            ${PROJECT_BINARY_DIR}/cmake/attiguardConfigVersion.cmake)
if(TARGET attiguard_core)
  list(APPEND attiguard_package_files ${PROJECT_SOURCE_DIR}/cmake/FindCSDP.cmake
                                      ${PROJECT_SOURCE_DIR}/cmake/FindIpopt.cmake)
endif()
install(FILES ${attiguard_package_files} DESTINATION ${ATTIGUARD_INSTALL_CMAKEDIR})

# pkg-config. The prefix is found from the .pc file's own place (${pcfiledir}), so that
# `cmake --install build --prefix <dir>` gives working files. The libraries are static, so
# attiguard.pc lists the full library's link-only dependencies in Libs (as found by this build:
# absolute paths).
file(RELATIVE_PATH ATTIGUARD_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" ATTIGUARD_PC_TO_PREFIX "${ATTIGUARD_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/attiguard-flight.pc.in
               ${PROJECT_BINARY_DIR}/pkgconfig/attiguard-flight.pc @ONLY)
set(attiguard_pc_files ${PROJECT_BINARY_DIR}/pkgconfig/attiguard-flight.pc)
if(TARGET attiguard_core)
  set(pc_libs ${CSDP_LIBRARY} ${LAPACK_LIBRARIES} ${ATTIGUARD_HDF5_LINK_LIBRARIES} -lm -pthread)
  if(ATTIGUARD_MPI AND MPI_CXX_FOUND)
    list(PREPEND pc_libs ${MPI_CXX_LINK_FLAGS} ${MPI_CXX_LIBRARIES})
  endif()
  list(JOIN pc_libs " " ATTIGUARD_PC_PRIVATE_LIBS)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/attiguard.pc.in
                 ${PROJECT_BINARY_DIR}/pkgconfig/attiguard.pc @ONLY)
  list(APPEND attiguard_pc_files ${PROJECT_BINARY_DIR}/pkgconfig/attiguard.pc)
endif()
install(FILES ${attiguard_pc_files} DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
