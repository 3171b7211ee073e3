# All dependencies are Debian 12 packages (see scripts/setup.sh); reached only through imported
# targets so that their headers are SYSTEM includes and our -Werror stays on our own code. The
# installed package config finds the same ones (cmake/coatfftConfig.cmake.in).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(GSL REQUIRED)
find_package(Boost 1.74 REQUIRED)
find_package(Threads REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/coatfft_fftw3.cmake)
# Seen from a project that adds coatfft with add_subdirectory, imported targets made here would
# be out of scope where that project links coatfft: make them global.
if(NOT PROJECT_IS_TOP_LEVEL)
  foreach(target Eigen3::Eigen GSL::gsl GSL::gslcblas Boost::headers Threads::Threads)
    if(TARGET ${target})
      get_target_property(global ${target} IMPORTED_GLOBAL)
      if(NOT global)
        set_target_properties(${target} PROPERTIES IMPORTED_GLOBAL TRUE)
      endif()
    endif()
  endforeach()
endif()
