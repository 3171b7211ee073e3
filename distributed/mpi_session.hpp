#pragma once
// MPI for the lifetime of a program's distributed run: MPI and FFTW's MPI library initialised at
// construction, finalised at destruction. Programs make one only when a launcher started them
// (launched()): a serial run never initialises MPI (a singleton MPI_Init costs about half a
// second with Open MPI).
#include "communicator.hpp"

namespace coatfft {

class MpiSession {
 public:
  /// MPI_Init_thread at MPI_THREAD_FUNNELED (FFTW's and the solver's threads never call MPI),
  /// FFTW's threads, then fftw_mpi_init (the order FFTW's manual 6.11 asks). Error when MPI was
  /// initialised already or gives less than funneled.
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  Communicator world() const { return Communicator::world(); }

  /// Whether an MPI launcher (mpirun, mpiexec) started this process: Open MPI's or PMI's rank
  /// variables are set (core/detail/mpi_launch.hpp).
  static bool launched();
};

}  // namespace coatfft
