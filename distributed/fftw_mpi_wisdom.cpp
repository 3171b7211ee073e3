#include "distributed/fftw_mpi_wisdom.hpp"

#include <fftw3-mpi.h>

#include <mutex>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "distributed/detail/mpi_handle.hpp"

namespace coatfft {

// The planner's lock: wisdom is the planner's state (convolution/fft/detail/fftw_plan.hpp).
void broadcast_fftw_wisdom(const Communicator& comm) {
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_mpi_broadcast_wisdom(detail::mpi_comm(comm));
}

void gather_fftw_wisdom(const Communicator& comm) {
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_mpi_gather_wisdom(detail::mpi_comm(comm));
}

}  // namespace coatfft
