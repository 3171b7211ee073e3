#include "distributed/slab.hpp"

#include <fftw3-mpi.h>

#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "distributed/detail/slab_fft.hpp"

namespace coatfft {

Slab slab_of(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny) {
  std::ptrdiff_t doubles = 0;
  return detail::slab_of(comm, nx, ny, doubles);
}

Slab detail::slab_of(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny,
                     std::ptrdiff_t& doubles) {
  COATFFT_REQUIRE(nx >= 2 && ny >= 2, "slab: nx = ", nx, " and ny = ", ny, " must be >= 2");
  // The transposes' layout: ny rows of nx/2 + 1 complex entries, then nx/2 + 1 rows of ny.
  const std::ptrdiff_t n[2] = {ny, nx / 2 + 1};
  Slab s;
  s.nx = nx;
  s.ny = ny;
  doubles = fftw_mpi_local_size_many_transposed(2, n, 2, FFTW_MPI_DEFAULT_BLOCK,
                                                FFTW_MPI_DEFAULT_BLOCK, detail::mpi_comm(comm),
                                                &s.rows, &s.y0, &s.columns, &s.kx0);
  // FFTW reports a start of 0 for a rank that holds nothing; the end of the grid keeps the starts
  // in rank order (a rank's start is the count before it).
  if (s.rows == 0) s.y0 = ny;
  if (s.columns == 0) s.kx0 = nx / 2 + 1;
  return s;
}

}  // namespace coatfft
