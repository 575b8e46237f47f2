# Finds the SuiteSparse components gapfem uses (Debian's libsuitesparse-dev ships no CMake config).
# Defines imported targets SuiteSparse::CHOLMOD and SuiteSparse::UMFPACK.
include(FindPackageHandleStandardArgs)
find_path(SuiteSparse_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(SuiteSparse_CHOLMOD_LIBRARY cholmod)
find_library(SuiteSparse_UMFPACK_LIBRARY umfpack)
find_library(SuiteSparse_CONFIG_LIBRARY suitesparseconfig)
find_library(SuiteSparse_AMD_LIBRARY amd)
find_library(SuiteSparse_COLAMD_LIBRARY colamd)
find_library(SuiteSparse_METIS_LIBRARY metis)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR
  SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_UMFPACK_LIBRARY SuiteSparse_CONFIG_LIBRARY
  SuiteSparse_METIS_LIBRARY)
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES IMPORTED_LOCATION ${SuiteSparse_CHOLMOD_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_AMD_LIBRARY};${SuiteSparse_COLAMD_LIBRARY};${SuiteSparse_METIS_LIBRARY};${SuiteSparse_CONFIG_LIBRARY}")
  add_library(SuiteSparse::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES IMPORTED_LOCATION ${SuiteSparse_UMFPACK_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "SuiteSparse::CHOLMOD;${SuiteSparse_AMD_LIBRARY};${SuiteSparse_CONFIG_LIBRARY}")
endif()
