#pragma once
// The periodic operator (convolution/operators/periodic_operator.hpp) on fields held in row slabs
// by the ranks of a communicator (distributed/slab.hpp): the circular convolution with the
// periodic influence coefficients of any FRF, by the slab transform of FFTW-MPI's steps. The
// coefficients' spectrum is computed distributed too, in the serial operator's steps (the lattice
// part's spectrum on this rank's half-spectrum columns, its inverse, the real-space part on this
// rank's rows, the mean removed over all ranks, the forward transform): no rank holds a whole
// field. Construction and apply() are collective.
#include <memory>

#include "../convolution/fft/planning.hpp"
#include "../convolution/kernels/periodic_kernel.hpp"
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "../frf/frf.hpp"
#include "communicator.hpp"
#include "slab.hpp"

namespace coatfft {

class DistributedPeriodicOperator {
 public:
  /// InvalidArgument as periodic_influence_kernel for the grid, the FRF and `kernel`'s options;
  /// `threads` (>= 1) FFTW's threads within each rank.
  DistributedPeriodicOperator(const Communicator& comm, const Grid& grid, const Frf& frf,
                              const PeriodicKernelOptions& kernel = {},
                              Planning planning = Planning::estimate, int threads = 1);
  ~DistributedPeriodicOperator();
  DistributedPeriodicOperator(DistributedPeriodicOperator&&) noexcept;
  DistributedPeriodicOperator& operator=(DistributedPeriodicOperator&&) noexcept;

  const Grid& grid() const { return grid_; }
  /// This rank's rows and half-spectrum columns.
  const Slab& slab() const;
  /// `displacement` [m] (resized to (nx, rows)) under `pressure` [Pa], both this rank's rows, of
  /// zero mean over the period. InvalidArgument for a pressure of another shape, or one with a
  /// value that is not finite (on any rank: every rank throws).
  void apply(const Field& pressure, Field& displacement);
  Field apply(const Field& pressure);
  /// The wall time apply() and the construction spent in the transforms' transposes so far [s]:
  /// the communication between the ranks, and the wait for the slowest.
  double communication_seconds() const;

 private:
  struct Transforms;
  Grid grid_;
  std::unique_ptr<Transforms> t_;
};

}  // namespace coatfft
