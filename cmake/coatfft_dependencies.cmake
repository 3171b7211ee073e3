# All dependencies are Debian 12 packages (see scripts/setup.sh); reached only through imported
# targets so that their headers are SYSTEM includes and our -Werror stays on our own code.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(GSL REQUIRED)
find_package(Boost 1.74 REQUIRED)
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
# FFTW 3.3.10 ships only pkg-config files; fftw3_threads is not listed in fftw3.pc.
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
find_library(COATFFT_FFTW3_THREADS fftw3_threads HINTS ${FFTW3_LIBRARY_DIRS} REQUIRED)
