#pragma once
// frf-split's coefficients (convolution/kernels/split_frf_kernel.hpp, docs/theory.md 4.5) by rows
// over the ranks of a communicator, for DistributedDcfftOperator: each rank computes the singular
// terms and the long range of its own rows of the quarter, as the serial kernel does them; the
// short range's alias fold is folded by rows and its 2-D DCT-I taken over the ranks (FFTW-MPI's
// transposes), its rows then sent to the ranks that hold them in the quarter. No rank holds the
// lattice or the quarter whole; the 1-D tables (the remainder's, the long range's Hankel table)
// are computed on every rank.
#include <cstddef>

#include "convolution/kernels/split_frf_kernel.hpp"
#include "core/grid.hpp"
#include "distributed/communicator.hpp"
#include "frf/frf.hpp"

namespace coatfft::detail {

/// Rows [y0, y0 + rows) of the quarter K(i, j), 0 <= i <= nx, of split_frf_kernel(grid, frf,
/// options) into `out` (rows x (nx + 1), x fastest; 0 in the slots nx and ny). Collective: every
/// rank calls it with its own rows. InvalidArgument as split_frf_kernel. `report`, when given,
/// receives the plan's choices and this rank's seconds.
void split_quarter_rows(const Communicator& comm, const Grid& grid, const Frf& frf,
                        const SplitKernelOptions& options, std::ptrdiff_t y0, std::ptrdiff_t rows,
                        double* out, SplitKernelReport* report = nullptr);

}  // namespace coatfft::detail
