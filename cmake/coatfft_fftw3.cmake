# FFTW3 as imported targets FFTW3::fftw3, FFTW3::fftw3_threads, and FFTW3::fftw3f and
# FFTW3::fftw3f_threads (single precision, the same Debian package), found on the machine that
# configures (coatfft's own build, or a consumer of the installed package: nothing of the build
# machine is recorded). FFTW 3.3.10 ships only pkg-config files, and fftw3_threads is not listed
# in fftw3.pc, so the libraries are located with find_library next to what pkg-config reports.
if(NOT TARGET FFTW3::fftw3)
  find_package(Threads REQUIRED)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(COATFFT_FFTW3 QUIET fftw3)
  endif()
  find_path(COATFFT_FFTW3_INCLUDE_DIR fftw3.h HINTS ${COATFFT_FFTW3_INCLUDE_DIRS} REQUIRED)
  # FFTW3::<library>, found next to what pkg-config reports; `depends` is what it links after it.
  function(coatfft_import_fftw library depends)
    string(TOUPPER "${library}" upper)
    find_library(COATFFT_${upper}_LIBRARY ${library} HINTS ${COATFFT_FFTW3_LIBRARY_DIRS} REQUIRED)
    add_library(FFTW3::${library} UNKNOWN IMPORTED GLOBAL)
    set_target_properties(FFTW3::${library} PROPERTIES
                          IMPORTED_LOCATION "${COATFFT_${upper}_LIBRARY}"
                          INTERFACE_INCLUDE_DIRECTORIES "${COATFFT_FFTW3_INCLUDE_DIR}"
                          INTERFACE_LINK_LIBRARIES "${depends}")
  endfunction()
  coatfft_import_fftw(fftw3 "")
  coatfft_import_fftw(fftw3_threads "FFTW3::fftw3;Threads::Threads")
  coatfft_import_fftw(fftw3f "")
  coatfft_import_fftw(fftw3f_threads "FFTW3::fftw3f;Threads::Threads")
endif()
# FFTW's MPI library (Debian's libfftw3-mpi-dev, built against Open MPI), for distributed runs:
# FFTW3::fftw3_mpi only where it is installed; the caller links MPI itself.
if(NOT TARGET FFTW3::fftw3_mpi)
  find_path(COATFFT_FFTW3_MPI_INCLUDE_DIR fftw3-mpi.h HINTS ${COATFFT_FFTW3_INCLUDE_DIR})
  find_library(COATFFT_FFTW3_MPI_LIBRARY fftw3_mpi HINTS ${COATFFT_FFTW3_LIBRARY_DIRS})
  if(COATFFT_FFTW3_MPI_INCLUDE_DIR AND COATFFT_FFTW3_MPI_LIBRARY)
    add_library(FFTW3::fftw3_mpi UNKNOWN IMPORTED GLOBAL)
    set_target_properties(FFTW3::fftw3_mpi PROPERTIES
                          IMPORTED_LOCATION "${COATFFT_FFTW3_MPI_LIBRARY}"
                          INTERFACE_INCLUDE_DIRECTORIES "${COATFFT_FFTW3_MPI_INCLUDE_DIR}"
                          INTERFACE_LINK_LIBRARIES FFTW3::fftw3)
  endif()
endif()
