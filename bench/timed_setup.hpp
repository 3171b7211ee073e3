#pragma once
// An operator built for a benchmark, with its setup split into the parts the benchmarks report:
// influence coefficients (or kernel samples), g(0), and the operator's own construction (FFTW
// plans and the kernel transform). make_operator builds every operator; where its report does not
// split the setup (Love's and frf-dcfft's coefficients), the kernel is made first and handed to
// make_operator.
#include "convolution/make_operator.hpp"
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

/// The operator of `options.method` for `body` on `grid`, timed by parts. Throws InvalidArgument
/// as make_operator does (direct and dcfft need a homogeneous body).
TimedSetup timed_setup(const Grid& grid, const LayerStack& body, const OperatorOptions& options);

}  // namespace coatfft::bench
