#pragma once
// FFTW wisdom across the ranks (FFTW's manual 6.8, "FFTW MPI Wisdom"): a program reads and writes
// its wisdom file on rank 0 only, and the ranks share what it holds, so that a wisdom file made by
// one run serves every rank's plans in the next.
#include "communicator.hpp"

namespace coatfft {

/// Every rank's FFTW wisdom gains rank 0's (fftw_mpi_broadcast_wisdom). Collective.
void broadcast_fftw_wisdom(const Communicator& comm);

/// Rank 0's FFTW wisdom gains every rank's (fftw_mpi_gather_wisdom). Collective.
void gather_fftw_wisdom(const Communicator& comm);

}  // namespace coatfft
