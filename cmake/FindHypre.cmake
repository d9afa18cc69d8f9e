# Debian's libhypre-dev ships neither a CMake config nor a pkg-config file: find the header and the
# library and wrap them in an imported target. hypre's headers include mpi.h, so MPI is always linked.
find_path(HYPRE_INCLUDE_DIR HYPRE_struct_ls.h PATH_SUFFIXES hypre REQUIRED)
find_library(HYPRE_LIBRARY NAMES HYPRE REQUIRED)
if(NOT TARGET Hypre::hypre)
  add_library(Hypre::hypre UNKNOWN IMPORTED)
  set_target_properties(Hypre::hypre PROPERTIES
    IMPORTED_LOCATION "${HYPRE_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${HYPRE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES MPI::MPI_CXX)
endif()
message(STATUS "hypre: ${HYPRE_LIBRARY} (headers in ${HYPRE_INCLUDE_DIR})")
