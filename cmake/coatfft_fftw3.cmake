# FFTW3 as imported targets FFTW3::fftw3, FFTW3::fftw3_threads, and FFTW3::fftw3f and
# FFTW3::fftw3f_threads (single precision, the same Debian package), found on the machine that
# configures (coatfft's own build, or a consumer of the installed package: nothing of the build
# machine is recorded). FFTW 3.3.10 ships only pkg-config files, and fftw3_threads is not listed
# in fftw3.pc, so both libraries are located with find_library next to what pkg-config reports.
if(NOT TARGET FFTW3::fftw3)
  find_package(Threads REQUIRED)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(COATFFT_FFTW3 QUIET fftw3)
  endif()
  find_path(COATFFT_FFTW3_INCLUDE_DIR fftw3.h HINTS ${COATFFT_FFTW3_INCLUDE_DIRS} REQUIRED)
  find_library(COATFFT_FFTW3_LIBRARY fftw3 HINTS ${COATFFT_FFTW3_LIBRARY_DIRS} REQUIRED)
  find_library(COATFFT_FFTW3_THREADS_LIBRARY fftw3_threads HINTS ${COATFFT_FFTW3_LIBRARY_DIRS}
               REQUIRED)
  find_library(COATFFT_FFTW3F_LIBRARY fftw3f HINTS ${COATFFT_FFTW3_LIBRARY_DIRS} REQUIRED)
  find_library(COATFFT_FFTW3F_THREADS_LIBRARY fftw3f_threads HINTS ${COATFFT_FFTW3_LIBRARY_DIRS}
               REQUIRED)
  add_library(FFTW3::fftw3 UNKNOWN IMPORTED GLOBAL)
  set_target_properties(FFTW3::fftw3 PROPERTIES IMPORTED_LOCATION "${COATFFT_FFTW3_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${COATFFT_FFTW3_INCLUDE_DIR}")
  add_library(FFTW3::fftw3_threads UNKNOWN IMPORTED GLOBAL)
  set_target_properties(FFTW3::fftw3_threads PROPERTIES
                        IMPORTED_LOCATION "${COATFFT_FFTW3_THREADS_LIBRARY}"
                        INTERFACE_LINK_LIBRARIES "FFTW3::fftw3;Threads::Threads")
  add_library(FFTW3::fftw3f UNKNOWN IMPORTED GLOBAL)
  set_target_properties(FFTW3::fftw3f PROPERTIES IMPORTED_LOCATION "${COATFFT_FFTW3F_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${COATFFT_FFTW3_INCLUDE_DIR}")
  add_library(FFTW3::fftw3f_threads UNKNOWN IMPORTED GLOBAL)
  set_target_properties(FFTW3::fftw3f_threads PROPERTIES
                        IMPORTED_LOCATION "${COATFFT_FFTW3F_THREADS_LIBRARY}"
                        INTERFACE_LINK_LIBRARIES "FFTW3::fftw3f;Threads::Threads")
endif()
