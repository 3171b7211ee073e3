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
#include "distributed_operator.hpp"

namespace coatfft {

namespace detail {
class SlabFft;
}  // namespace detail

class DistributedPeriodicOperator final : public DistributedOperator {
 public:
  /// InvalidArgument as periodic_influence_kernel for the grid, the FRF and `kernel`'s options;
  /// `threads` (>= 1) FFTW's threads within each rank; `method` what method() reports (the
  /// periodic kernel is the exact one for dcfft and frf-split alike, as make_operator's).
  DistributedPeriodicOperator(const Communicator& comm, const Grid& grid, const Frf& frf,
                              const PeriodicKernelOptions& kernel = {},
                              Planning planning = Planning::estimate, int threads = 1,
                              Method method = Method::frf_split);
  ~DistributedPeriodicOperator();

  Method method() const override { return method_; }
  bool periodic() const override { return true; }
  const Slab& slab() const override;
  /// The displacement of zero mean over the period (distributed/distributed_operator.hpp).
  void apply(const Field& pressure, Field& displacement) override;
  using SurfaceOperator::apply;
  double communication_seconds() const override;
  /// Its slab transform: a contact solver's preconditioner on the same fields shares it (its
  /// half spectra are scratch of each application).
  const std::shared_ptr<detail::SlabFft>& slab_fft() const;
  /// The same body on the grid with half the cells per side, by the Galerkin coarse kernel of
  /// the serial operator's coarsened() (convolution/kernels/detail/coarse_kernel.hpp), each rank
  /// holding the coarse rows of its own pairs of rows: nullptr (on every rank) when a rank's
  /// rows do not pair up or FFTW's coarse slabs are not those halves. Collective.
  std::unique_ptr<SurfaceOperator> coarsened() override;

 private:
  struct Transforms;
  // From this rank's rows of the kernel, on the slab transform `fft` of `grid`.
  DistributedPeriodicOperator(const Communicator& comm, const Grid& grid,
                              std::shared_ptr<detail::SlabFft> fft, Field kernel_rows, int threads,
                              Method method);
  Method method_;
  int threads_;
  std::unique_ptr<Transforms> t_;
};

}  // namespace coatfft
