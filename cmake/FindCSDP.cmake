# FindCSDP: the CSDP semidefinite-programming library (Debian libsdp-dev, EPL) that ConReach's
# SDPs use (src/attiguard/reach/sdp_solver.cpp, docs/reach.md).
#
# Defines the imported target CSDP::CSDP (library, include directory, BLAS/LAPACK and libm as its
# own link dependencies) and CSDP_FOUND, CSDP_INCLUDE_DIR, CSDP_LIBRARY. The static libsdp.a is
# preferred: reach/sdp_solver.cpp defines CSDP's initparams() so that parameters never come
# from ./param.csdp and nothing is printed, and with the archive that definition is the only one
# linked. Used by attiguard's own build and, installed next to attiguardConfig.cmake, by
# find_package(attiguard), so that a downstream project links attiguard::attiguard (a static
# library) without naming CSDP itself.
include(FindPackageHandleStandardArgs)

find_path(CSDP_INCLUDE_DIR csdp/declarations.h)
find_library(CSDP_LIBRARY NAMES libsdp.a sdp)
find_package_handle_standard_args(CSDP REQUIRED_VARS CSDP_LIBRARY CSDP_INCLUDE_DIR)

if(CSDP_FOUND AND NOT TARGET CSDP::CSDP)
  find_package(LAPACK REQUIRED)  # LAPACK::LAPACK (with BLAS)
  add_library(CSDP::CSDP UNKNOWN IMPORTED)
  set_target_properties(CSDP::CSDP PROPERTIES
    IMPORTED_LOCATION "${CSDP_LIBRARY}"
    IMPORTED_LINK_INTERFACE_LANGUAGES C
    INTERFACE_INCLUDE_DIRECTORIES "${CSDP_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "LAPACK::LAPACK;m")
endif()
mark_as_advanced(CSDP_INCLUDE_DIR CSDP_LIBRARY)
