# Whether the Python module (python/) is built: COATFFT_PYTHON asks for it, and it is built when
# Debian's python3 with its development files and pybind11 are found. Sanitized and fuzzing builds
# leave it out: an extension built with ASan cannot be loaded by an uninstrumented interpreter.
#
# The interpreter is Debian's /usr/bin/python3 unless Python3_EXECUTABLE says otherwise (pip passes
# its own): the python3 first on PATH may be another installation, without numpy.
set(COATFFT_PYTHON_FOUND OFF)
if(COATFFT_PYTHON AND (COATFFT_SANITIZE OR COATFFT_FUZZ))
  message(STATUS "coatfft: Python module not built in a sanitized or fuzzing build")
elseif(COATFFT_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 3.9 COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 CONFIG QUIET)
  if(Python3_FOUND AND pybind11_FOUND)
    set(COATFFT_PYTHON_FOUND ON)
    # The module links the static libraries into a shared object.
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  else()
    message(STATUS "coatfft: Python module not built (needs python3-dev and pybind11-dev)")
  endif()
endif()
