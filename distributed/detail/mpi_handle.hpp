#pragma once
// The MPI communicator behind a Communicator, for the library's own sources (MPI is private).
#include <mpi.h>

#include "distributed/communicator.hpp"

namespace coatfft {

struct Communicator::Handle {
  MPI_Comm comm;
};

namespace detail {
inline MPI_Comm mpi_comm(const Communicator& c) {
  return c.handle().comm;
}
}  // namespace detail

}  // namespace coatfft
