# FindIpopt: the IPOPT interior-point NLP solver (Debian coinor-libipopt-dev, EPL) that the slew
# planner uses (src/attiguard/plan/transcription_nlp.cpp, docs/slew-planner.md).
#
# Defines the imported target Ipopt::Ipopt and Ipopt_FOUND, Ipopt_INCLUDE_DIR, Ipopt_LIBRARY.
# The target links libipopt alone, never the libraries that ipopt.pc lists after it: Debian's
# IPOPT uses the sequential MUMPS, and libdmumps_seq / libmumps_common_seq define dummy C
# MPI_Init, MPI_Comm_rank, MPI_Finalize and MPI_Wtime. Named directly on the link line (as
# `pkg-config --libs ipopt` does), they come before OpenMPI's libmpi in the program's symbol
# lookup, so MPI_Init binds to the dummy and the real MPI_Comm_size then aborts ("called before
# MPI_INIT"). Reached only through libipopt's own DT_NEEDED entries, they come after every
# library the program names, and MPI's real symbols win (docs/install.md).
# Used by attiguard's own build and, installed next to attiguardConfig.cmake, by
# find_package(attiguard).
include(FindPackageHandleStandardArgs)

find_path(Ipopt_INCLUDE_DIR IpTNLP.hpp PATH_SUFFIXES coin coin-or)
find_library(Ipopt_LIBRARY NAMES ipopt)
find_package_handle_standard_args(Ipopt REQUIRED_VARS Ipopt_LIBRARY Ipopt_INCLUDE_DIR)

if(Ipopt_FOUND AND NOT TARGET Ipopt::Ipopt)
  add_library(Ipopt::Ipopt UNKNOWN IMPORTED)
  # HAVE_CSTDDEF: IPOPT 3.11's IpoptConfig.h otherwise falls back to <stddef.h> guesses (the
  # definition ipopt.pc's cflags carry).
  set_target_properties(Ipopt::Ipopt PROPERTIES
    IMPORTED_LOCATION "${Ipopt_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Ipopt_INCLUDE_DIR}"
    INTERFACE_COMPILE_DEFINITIONS "HAVE_CSTDDEF")
endif()
mark_as_advanced(Ipopt_INCLUDE_DIR Ipopt_LIBRARY)
