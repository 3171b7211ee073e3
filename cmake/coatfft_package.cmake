# coatfft as a CMake package: public headers, install rules and the package config.
include(CMakePackageConfigHelpers)

set(COATFFT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/coatfft)

# coatfft_public_headers(header...): headers of the calling folder that users include, as
# <coatfft/FOLDER/header>. Each is linked into ${PROJECT_BINARY_DIR}/include/coatfft/FOLDER (the
# build-tree include root of coatfft::coatfft, so add_subdirectory users see exactly what an
# install holds) and installed to include/coatfft/FOLDER. A public header includes other public
# headers by relative path ("../core/grid.hpp"), which resolves the same in the source tree, the
# build tree and an install. Headers not listed here are private: not linked, not installed.
function(coatfft_public_headers)
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  set(destination coatfft)
  if(folder)
    set(destination coatfft/${folder})
  endif()
  file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/include/${destination})
  foreach(header IN LISTS ARGN)
    file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR}/${header}
         ${PROJECT_BINARY_DIR}/include/${destination}/${header} SYMBOLIC)
    install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${destination})
    set_property(GLOBAL APPEND PROPERTY COATFFT_PUBLIC_HEADERS ${destination}/${header})
  endforeach()
endfunction()

# The public surface, checked where it is defined (after every coatfft_public_headers): the
# umbrella coatfft.hpp includes every other public header (at configure time), and, with
# COATFFT_CHECK_HEADERS, each public header compiles on its own with only the include root a user
# has (the build tree's, which mirrors an install) and Eigen: the target coatfft_header_check, one
# object per header, rebuilt only when its header changes.
function(coatfft_check_public_headers)
  get_property(headers GLOBAL PROPERTY COATFFT_PUBLIC_HEADERS)
  file(READ ${PROJECT_SOURCE_DIR}/coatfft.hpp umbrella)
  set(missing)
  foreach(header IN LISTS headers)
    string(REGEX REPLACE "^coatfft/" "" relative ${header})
    string(FIND "${umbrella}" "#include \"${relative}\"" at)
    if(at LESS 0 AND NOT relative STREQUAL "coatfft.hpp")
      list(APPEND missing ${relative})
    endif()
  endforeach()
  if(missing)
    list(JOIN missing ", " missing)
    message(FATAL_ERROR "coatfft.hpp must include every public header; it misses ${missing}")
  endif()
  if(NOT COATFFT_CHECK_HEADERS)
    return()
  endif()
  set(sources)
  foreach(header IN LISTS headers)
    string(MAKE_C_IDENTIFIER ${header} name)
    set(source ${PROJECT_BINARY_DIR}/header_check/${name}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "#include <${header}>\n")
    list(APPEND sources ${source})
  endforeach()
  add_library(coatfft_header_check OBJECT ${sources})
  # Each header on its own, whatever COATFFT_UNITY says: a batch would hide what one lacks.
  set_target_properties(coatfft_header_check PROPERTIES UNITY_BUILD OFF)
  target_link_libraries(coatfft_header_check PRIVATE coatfft)
  coatfft_target_warnings(coatfft_header_check)
endfunction()

# The library, its export set (relocatable: paths relative to the install prefix, dependencies
# by imported target) and the package config with its version file.
function(coatfft_install_package)
  install(TARGETS coatfft EXPORT coatfftTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT coatfftTargets NAMESPACE coatfft:: DESTINATION ${COATFFT_INSTALL_CMAKEDIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/coatfftConfig.cmake.in
                                ${PROJECT_BINARY_DIR}/coatfftConfig.cmake
                                INSTALL_DESTINATION ${COATFFT_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/coatfftConfigVersion.cmake
                                   COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/coatfftConfig.cmake
                ${PROJECT_BINARY_DIR}/coatfftConfigVersion.cmake
                ${PROJECT_SOURCE_DIR}/cmake/coatfft_fftw3.cmake
          DESTINATION ${COATFFT_INSTALL_CMAKEDIR})
endfunction()
