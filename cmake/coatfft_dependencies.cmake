# All dependencies are Debian 12 packages (see scripts/setup.sh); reached only through imported
# targets so that their headers are SYSTEM includes and our -Werror stays on our own code. The
# installed package config finds the same ones (cmake/coatfftConfig.cmake.in).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(GSL REQUIRED)
find_package(Boost 1.74 REQUIRED)
find_package(Threads REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/coatfft_fftw3.cmake)
# Distributed runs (distributed/, docs/scale.md) need MPI (its C interface, used from C++; Open MPI
# on Debian, the one FFTW's MPI library is built against), FFTW3::fftw3_mpi, and, where the scene
# layer is built (the program or the Python module), NetCDF's MPI build with PnetCDF for their
# NetCDF files (topography/CMakeLists.txt). COATFFT_MPI is on by default where all are found; OFF
# builds the serial library and programs only.
set(MPI_CXX_SKIP_MPICXX ON)
find_package(MPI QUIET COMPONENTS CXX)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(COATFFT_NETCDF_MPI QUIET IMPORTED_TARGET GLOBAL netcdf-pnetcdf)
endif()
set(coatfft_mpi_default OFF)
if(MPI_CXX_FOUND AND TARGET FFTW3::fftw3_mpi
   AND (COATFFT_NETCDF_MPI_FOUND OR NOT (COATFFT_BUILD_CLI OR COATFFT_PYTHON_FOUND)))
  set(coatfft_mpi_default ON)
endif()
option(COATFFT_MPI "Build the distributed operators and runs on FFTW-MPI (docs/scale.md)"
       ${coatfft_mpi_default})
if(COATFFT_MPI AND NOT coatfft_mpi_default)
  message(FATAL_ERROR "COATFFT_MPI=ON needs MPI and FFTW's MPI library, and with the program or "
                      "the Python module NetCDF's PnetCDF build: Debian's libopenmpi-dev, "
                      "libfftw3-mpi-dev and libnetcdf-pnetcdf-dev (scripts/setup.sh installs "
                      "them)")
endif()
# Seen from a project that adds coatfft with add_subdirectory, imported targets made here would
# be out of scope where that project links coatfft: make them global.
if(NOT PROJECT_IS_TOP_LEVEL)
  foreach(target Eigen3::Eigen GSL::gsl GSL::gslcblas Boost::headers Threads::Threads MPI::MPI_CXX)
    if(TARGET ${target})
      get_target_property(global ${target} IMPORTED_GLOBAL)
      if(NOT global)
        set_target_properties(${target} PROPERTIES IMPORTED_GLOBAL TRUE)
      endif()
    endif()
  endforeach()
endif()
