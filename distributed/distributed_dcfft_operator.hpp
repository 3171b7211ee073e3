#pragma once
// DC-FFT (Liu, Wang and Liu 2000; docs/theory.md section 1.3) on fields held in row slabs by the
// ranks of a communicator (distributed/slab.hpp): the free surface's linear convolution with
// Love's (1929) coefficients of a homogeneous half-space, or with frf-split's coefficients of any
// FRF (a coated body's; convolution/kernels/split_frf_kernel.hpp), by a pruned slab transform of
// the zero-padded (2nx, 2ny) lattice. Only the nx real values of each row are transformed (FFTW's
// r2c of length 2nx on the row and its zeros), FFTW-MPI transposes the (ny, nx + 1) half spectrum's
// rows into columns, and each column's ny entries, padded to 2ny, take a c2c of length 2ny; back
// the same way, keeping the first ny entries of each column and nx of each row. The padded rows
// are never distributed: every rank holds about ny / P of the real rows, where a padded slab
// would give the real rows to the first half of the ranks; the rows' half spectra are taken in
// place and the columns in cache-sized blocks, as the serial DcfftOperator does. The coefficients'
// real spectrum is computed distributed too, as the 2-D DCT-I of their quarter (each rank its
// rows, FFTW-MPI's transpose, each rank its columns); frf-split's quarter rows are computed on
// each rank, its short-range lattice transformed distributed as well
// (distributed/detail/distributed_split_kernel.hpp). Construction and apply() are collective.
#include <cstddef>
#include <functional>
#include <memory>

#include "../convolution/fft/planning.hpp"
#include "../convolution/kernels/split_frf_kernel.hpp"
#include "../core/grid.hpp"
#include "../frf/frf.hpp"
#include "distributed_operator.hpp"

namespace coatfft {

class DistributedDcfftOperator final : public DistributedOperator {
 public:
  /// Love's coefficients of a homogeneous half-space of plane-strain modulus E* [Pa] (finite,
  /// > 0) on `grid`; `threads` (>= 1) FFTW's threads within each rank. InvalidArgument otherwise.
  DistributedDcfftOperator(const Communicator& comm, const Grid& grid, double plane_strain_modulus,
                           Planning planning = Planning::estimate, int threads = 1);
  /// frf-split's coefficients of `frf` on `grid` (split_frf_kernel's, to rounding: the quarter's
  /// rows are the serial kernel's, the short range's lattice is transformed over the ranks);
  /// `options.threads` its loops' threads, `threads` FFTW's. InvalidArgument as split_frf_kernel.
  /// `report`, when given, receives split_frf_kernel's diagnostics (this rank's seconds).
  DistributedDcfftOperator(const Communicator& comm, const Grid& grid, const Frf& frf,
                           const SplitKernelOptions& options = {},
                           Planning planning = Planning::estimate, int threads = 1,
                           SplitKernelReport* report = nullptr);
  ~DistributedDcfftOperator();

  Method method() const override { return method_; }
  const Slab& slab() const override;
  /// The free surface's displacement (distributed/distributed_operator.hpp).
  void apply(const Field& pressure, Field& displacement) override;
  using SurfaceOperator::apply;
  double communication_seconds() const override;

  /// Fills this rank's rows [y0, y0 + rows) of the coefficients' quarter (nx + 1 each, x
  /// fastest); called collectively.
  using QuarterRowsFunction = std::function<void(std::ptrdiff_t y0, std::ptrdiff_t rows, double*)>;

 private:
  struct Transforms;
  DistributedDcfftOperator(const Communicator& comm, const Grid& grid, Method method,
                           Planning planning, int threads, const QuarterRowsFunction& quarter_rows);
  void convolve_columns();
  Method method_;
  std::unique_ptr<Transforms> t_;
};

}  // namespace coatfft
