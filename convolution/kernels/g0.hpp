#pragma once
// The zero-frequency sample g(0) of a spectral kernel: every FRF is singular at k = 0
// (H ~ C0 / k), so the sample at the origin of the frequency lattice is replaced by the mean of H
// over the central lattice cell [-dkx/2, dkx/2] x [-dky/2, dky/2] (docs/theory.md section 3;
// Spinu 2021, section 4, step 3, where it is "computed by quadrature").
#include <string_view>

#include "../../frf/frf.hpp"

namespace coatfft {

/// How g(0) is computed.
enum class G0Method {
  /// C0 * mean(1/|k|) in closed form (docs/theory.md 3.1) plus the mean of the bounded remainder
  /// H(k) - C0/k, integrated in polar form where it is smooth (docs/theory.md 3.2-3.3). Fast and
  /// accurate to ~1e-14 relative.
  regularized,
  /// Plain adaptive quadrature of the singular H over the cell (the quad2d approach of Spinu 2021),
  /// by GSL: the 2-D integral over a quadrant, whose corner holds the 1/k singularity, iterated as
  /// 1-D QAGS integrals (Matlab's integral2 'iterated' method; GSL has no 2-D adaptive rule).
  /// Slower, accurate to about its tolerance; kept to reproduce Spinu (2021), Figure 3(b).
  quadrature,
  /// Not computed: g(0) = 0. A g(0) error only shifts the displacement by a constant
  /// (dg * load / period area; Spinu 2021, Figure 3(b)), so where only relative displacements
  /// matter — a load-controlled contact, whose approach then goes unreported — g(0) is not needed
  /// at all.
  omitted,
};

/// "regularized", "quadrature" or "omitted".
std::string_view to_string(G0Method method);
/// The G0Method named `name`; throws InvalidArgument naming the valid names otherwise.
G0Method parse_g0_method(std::string_view name);

/// g(0) and how it was obtained.
struct G0Result {
  double value;            ///< g(0) [m/Pa]: mean of H over the central frequency cell
  G0Method method;         ///< method used
  double seconds;          ///< wall-clock time of the computation [s]
  double estimated_error;  ///< quadrature error estimate of `value` [m/Pa] (absolute)
};

/// Default relative tolerance for compute_g0 (reached by `regularized` for every FRF of frf/).
inline constexpr double default_g0_tolerance = 1e-13;

/// Closed-form mean of 1/|k| over [-dkx/2, dkx/2] x [-dky/2, dky/2] [m/rad] (docs/theory.md 3.1):
/// (2/dky) asinh(dky/dkx) + (2/dkx) asinh(dkx/dky). dkx, dky [rad/m] finite and > 0.
double mean_inverse_wavenumber(double dkx, double dky);

/// g(0) for `frf` on a frequency lattice of spacings dkx = 2 pi / period_x and
/// dky = 2 pi / period_y [rad/m]. `tolerance` (> 0, finite) is the requested accuracy relative to
/// g(0) (for `regularized`, relative to its closed-form part C0 mean(1/|k|), the same order).
/// `omitted` returns {0, omitted, 0, 0} without evaluating H. If the quadrature cannot reach the
/// tolerance (GSL's workspace full, or rounding), the result carries GSL's error estimate in
/// `estimated_error`. Throws InvalidArgument on bad spacings or tolerance, or if g(0) is not
/// finite (H not finite on the cell).
G0Result compute_g0(const Frf& frf, double dkx, double dky, G0Method method,
                    double tolerance = default_g0_tolerance);

}  // namespace coatfft
