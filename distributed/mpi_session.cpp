#include "distributed/mpi_session.hpp"

#include <fftw3-mpi.h>
#include <mpi.h>

#include <mutex>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "core/detail/mpi_launch.hpp"
#include "core/error.hpp"

namespace coatfft {

MpiSession::MpiSession(int& argc, char**& argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  COATFFT_REQUIRE(!initialised, "MpiSession: MPI is initialised already");
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  COATFFT_REQUIRE(provided >= MPI_THREAD_FUNNELED,
                  "MpiSession: MPI does not support threads that leave MPI calls to the main one");
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  detail::set_planner_threads_locked(1);  // fftw_init_threads before fftw_mpi_init
  fftw_mpi_init();
}

MpiSession::~MpiSession() {
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_mpi_cleanup();
  }
  MPI_Finalize();
}

bool MpiSession::launched() {
  return detail::mpi_launch().launched;
}

}  // namespace coatfft
