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
  endforeach()
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
