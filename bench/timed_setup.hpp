#pragma once
// An operator built for a benchmark, with its setup split into the parts the benchmarks report:
// influence coefficients (or kernel samples), g(0), and the operator's own construction (FFTW
// plans and the kernel transform), all read off make_operator's report.
#include "convolution/operators/make_operator.hpp"
#include "core/grid.hpp"
#include "layers/layer_stack.hpp"

namespace coatfft::bench {

struct TimedSetup {
  BuiltOperator built;
  /// Influence coefficients or kernel samples [s]: Love's (direct, dcfft), frf_dcfft_kernel's
  /// (frf-dcfft: the FRF samples at alpha = 2, plus their inverse DCT otherwise), the split
  /// kernel (frf-split); 0 for frf-spectral, which has none.
  double kernel_s = 0.0;
  double g0_s = 0.0;         ///< g(0) (frf-spectral, frf-dcfft) [s]
  double transform_s = 0.0;  ///< the rest: plans, kernel transform (frf-spectral: FRF sampling)
  double setup_s = 0.0;      ///< wall time of the whole build [s]
};

/// make_operator(grid, body, options), its setup split by parts. Throws InvalidArgument as
/// make_operator does (direct and dcfft need a homogeneous body).
TimedSetup timed_setup(const Grid& grid, const LayerStack& body, const OperatorOptions& options);

}  // namespace coatfft::bench
