#pragma once
// FRF-spectral displacement operator (Spinu 2021, section 4, first algorithm;
// docs/theory.md 4.3): the pressure, zero-padded to an alpha-times larger periodic domain, is
// multiplied in Fourier space by the FRF sampled on that domain's frequency lattice, with the
// singular zero-frequency sample replaced by g(0) (convolution/kernels/g0.hpp). This is a
// convolution with the (alpha L)-periodised Green's function, so it carries a periodicity error
// ~1/alpha that is uniform in N (docs/theory.md 4.3: -2.5% centre, -4.7% domain edge for Hertz at
// alpha = 2).
#include <cstddef>
#include <string>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/detail/frf_lattice.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/operators/surface_operator.hpp"
#include "frf/frf.hpp"

namespace coatfft {

/// u = IFFT_M[ H . FFT_M(p zero-padded) ] restricted to the target grid, M = alpha N per axis.
/// Built once (FRF sampling, g(0), FFTW plans on owned buffers); apply() only transforms.
class FrfSpectralOperator final : public SurfaceOperator {
 public:
  /// alpha: domain extension ratio (>= 1, alpha nx and alpha ny integers); g(0) is computed by
  /// `g0_method` to relative tolerance `g0_tolerance`; `planning`/`threads` as for FFTW plans
  /// (the threads also sample the FRF, see sample_frf_half_spectrum).
  FrfSpectralOperator(const Grid& grid, const Frf& frf, double alpha, G0Method g0_method,
                      double g0_tolerance = default_g0_tolerance,
                      Planning planning = Planning::estimate, int threads = 1);
  /// As above with a given g(0) (e.g. a value from a scene file, or a deliberately perturbed one:
  /// Spinu (2021), Figure 3(b)); `g0.value` must be finite.
  FrfSpectralOperator(const Grid& grid, const Frf& frf, double alpha, const G0Result& g0,
                      Planning planning = Planning::estimate, int threads = 1);

  const Grid& grid() const override { return grid_; }
  /// Throws InvalidArgument unless `pressure` has shape (nx, ny) and does not alias
  /// `displacement`.
  void apply(const Field& pressure, Field& displacement) override;
  Method method() const override { return Method::frf_spectral; }
  using SurfaceOperator::apply;

  /// The g(0) used, with its method, cost and error estimate.
  const G0Result& g0() const { return g0_; }
  /// Domain extension ratio alpha and the extended lattice sizes M = alpha N.
  double alpha() const { return alpha_; }
  std::ptrdiff_t extended_nx() const { return mx_; }
  std::ptrdiff_t extended_ny() const { return my_; }
  /// Wall-clock seconds of the constructor (g(0), FRF sampling, FFTW planning) [s].
  double setup_seconds() const { return setup_seconds_; }

 private:
  Grid grid_;
  double alpha_;
  std::ptrdiff_t mx_;
  std::ptrdiff_t my_;
  std::ptrdiff_t hx_;  // mx/2 + 1
  G0Result g0_;
  FftwRealBuffer real_;         // (my, mx) padded pressure, then displacement
  FftwComplexBuffer spectrum_;  // (my, hx) scratch spectrum (c2r destroys it)
  // H / (mx my) on the quarter 0 <= jx <= mx/2, 0 <= jy <= my/2 (hx x (my/2 + 1), x fastest):
  // H is real and even in ky, so the rows -jy of the half spectrum read row jy.
  Field kernel_quarter_;
  FftwPlan forward_;
  FftwPlan backward_;
  double setup_seconds_ = 0.0;
};

}  // namespace coatfft
