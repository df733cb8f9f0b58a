# FindSuiteSparse: SuiteSparse components as the targets SuiteSparse >= 7 exports
# (SuiteSparse::UMFPACK, SuiteSparse::KLU, ...). Debian 12 ships 5.12 with neither a CMake
# config nor pkg-config files, so after trying the config we search for headers and libraries.
include(FindPackageHandleStandardArgs)

if(NOT SuiteSparse_FIND_COMPONENTS)
  set(SuiteSparse_FIND_COMPONENTS UMFPACK KLU)
endif()

foreach(component IN LISTS SuiteSparse_FIND_COMPONENTS)
  if(TARGET SuiteSparse::${component})
    set(SuiteSparse_${component}_FOUND TRUE)
    continue()
  endif()
  find_package(${component} CONFIG QUIET)
  if(TARGET SuiteSparse::${component})
    set(SuiteSparse_${component}_FOUND TRUE)
    continue()
  endif()
  string(TOLOWER ${component} lower)
  find_path(SuiteSparse_${component}_INCLUDE_DIR ${lower}.h PATH_SUFFIXES suitesparse)
  find_library(SuiteSparse_${component}_LIBRARY ${lower})
  mark_as_advanced(SuiteSparse_${component}_INCLUDE_DIR SuiteSparse_${component}_LIBRARY)
  if(SuiteSparse_${component}_INCLUDE_DIR AND SuiteSparse_${component}_LIBRARY)
    set(SuiteSparse_${component}_FOUND TRUE)
    add_library(SuiteSparse::${component} UNKNOWN IMPORTED)
    # Eigen's support modules include <umfpack.h> without the suitesparse/ prefix.
    set_target_properties(SuiteSparse::${component} PROPERTIES
      IMPORTED_LOCATION "${SuiteSparse_${component}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_${component}_INCLUDE_DIR}")
  endif()
endforeach()

find_package_handle_standard_args(SuiteSparse HANDLE_COMPONENTS
  REQUIRED_VARS SuiteSparse_FIND_COMPONENTS)
