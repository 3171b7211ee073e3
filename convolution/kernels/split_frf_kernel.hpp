#pragma once
// "frf-split": DC-FFT influence coefficients of any layered FRF, built so that the homogeneous
// half-space gives Love's coefficients exactly and a coated body converges like Love's DC-FFT
// (docs/split_kernel.md). The FRF is split as
//
//   H(k) = Cinf/k + (C0 - Cinf) exp(-beta k)/k + R(k),
//
// (a) Cinf/k: Love's cell-averaged coefficients (docs/theory.md (1.5)), exact;
// (b) exp(-beta k)/k <-> 1/(2 pi sqrt(r^2 + beta^2)): its cell integral in closed form;
// (c) R(k): bounded, O(k^0) at k = 0, decaying fast. R is split once more with the window
//     w = exp(-s) (1 + s + s^2/2), s = (sigma k)^2 (an Ewald-type split): R w has a smooth,
//     long-range kernel that is tabulated by a 1-D Hankel transform and integrated over each cell
//     in space (no periodisation), and R (1 - w) = O(k^6) R has a short-range kernel whose
//     cell-averaged coefficients are summed on a periodic lattice with every alias
//     k + 2 pi (p/dx, q/dy) folded in (no truncation at Nyquist). Along a cell side >= 128 sigma
//     (a wide axis) the short kernel lies within the cell's own row and the lattice reduces to
//     its k = 0 term; beyond 128 sigma_e from the origin the long-range kernel is tabulated in
//     log r. The cost is then bounded by the grid size, not by the cells' or the domain's aspect
//     ratio (docs/split_kernel.md, section 7).
#include <cstddef>

#include "../../core/grid.hpp"
#include "../../frf/frf.hpp"
#include "influence_kernel.hpp"

namespace coatfft {

/// How the bounded remainder R(k) of the split is turned into influence coefficients.
enum class SplitRoute {
  automatic,  ///< the windowed split: long-range part by Hankel, short-range on the lattice
  periodic,   ///< all of R on the periodic lattice of period (2nx dx, 2ny dy), aliases folded
              ///< (periodisation error of R's r^-3 tail: accurate for coatings thin against L only)
  hankel,     ///< all of R by the Hankel table and space quadrature (cost grows like (L/h)^2 and
              ///< cells are subdivided when a layer is thinner than a cell: for comparison)
};

struct SplitKernelOptions {
  /// Length beta [m] of the (C0 - Cinf) exp(-beta k)/k term; 0 picks it from the FRF so that the
  /// exponential has the same first moment as k H - Cinf (about the coating thickness).
  double beta = 0.0;
  /// Length sigma [m] of the window of the automatic route; 0 picks
  /// max(min(lx, ly)/32, 1.5 min(dx, dy)), or the long side / 128 for cells >= 8 times longer
  /// than wide whose long side would need more than 4 aliases (docs/split_kernel.md, section 7).
  /// The result does not depend on it (to the tolerance); the cost does. A sigma so large against
  /// a cell that the short-range lattice would exceed 2^27 entries is refused.
  double sigma = 0.0;
  SplitRoute route = SplitRoute::automatic;
  /// Relative tolerance [-] of every truncation (k cut-offs, alias series, Hankel table, cell
  /// quadrature), measured against Cinf; in (0, 1e-3].
  double tolerance = 1e-11;
  /// Largest alias order |p|, |q| folded on the lattice (>= 0). Only coatings much thinner than a
  /// cell need many (about 3 dx/h); beyond the cap the fold is truncated (see report).
  int max_alias_order = 48;
  /// Threads for the coefficient loops (Love, corner table, Hankel table, cell quadrature, alias
  /// fold); the result does not depend on it. In [1, max_threads] (core/threads.hpp).
  int threads = 1;
};

/// What split_frf_kernel did, for benchmarks and the validation table.
struct SplitKernelReport {
  double c0 = 0.0;              ///< lim k H [1/Pa]
  double c_inf = 0.0;           ///< lim_{k->inf} k H [1/Pa]
  double beta = 0.0;            ///< beta used [m]
  double sigma = 0.0;           ///< window length used [m] (0: periodic route, inf: Hankel route)
  bool remainder_zero = false;  ///< R vanished to rounding (homogeneous or identical layers)
  int alias_order = 0;          ///< largest alias order folded
  bool alias_capped = false;    ///< the fold needed more than max_alias_order
  std::ptrdiff_t hankel_r_points = 0;  ///< radii of the Hankel table
  std::ptrdiff_t hankel_k_nodes = 0;   ///< quadrature nodes per radius
  int cell_rule = 0;     ///< Gauss-Legendre nodes per cell side (incl. subdivision); 1: point
                         ///< values and the 9-point cell-average stencil; 0: panels graded
                         ///< in r along a cell side longer than ~5 sigma
  bool wide_x = false;   ///< the short-range lattice reduced to k = 0 along x (dx >= 128 sigma)
  bool wide_y = false;   ///< the same along y
  double seconds = 0.0;  ///< wall-clock time of the whole construction [s]
  double seconds_long = 0.0;   ///< of which the Hankel table and cell quadrature [s]
  double seconds_short = 0.0;  ///< of which the alias fold and its DCT [s]
};

/// Influence coefficients K(di, dj) [m/Pa] of the FRF `frf` on `grid` by the split above
/// (coefficient form, Method::frf_split). Exactly Love's coefficients for a homogeneous FRF
/// (C0 == Cinf and R == 0 to rounding). Throws InvalidArgument for bad options or an FRF whose c0,
/// c_inf or values are not finite and positive. `report`, when given, receives the diagnostics.
InfluenceKernel split_frf_kernel(const Grid& grid, const Frf& frf,
                                 const SplitKernelOptions& options = {},
                                 SplitKernelReport* report = nullptr);

/// The work split_frf_kernel would do on `grid` for `frf`, counted from its plan without
/// computing any coefficient (the plan scans the FRF: about a millisecond): the inputs of the
/// setup-time model of the automatic method choice (model/auto_method.hpp, docs/auto.md).
/// The counts are proportional to the time of each part, not exact operation counts.
struct SplitKernelWork {
  double hankel_evaluations = 0.0;  ///< Bessel evaluations of the long-range table
  double cell_nodes = 0.0;          ///< table lookups of the long-range cell integrals
  double fold_terms = 0.0;          ///< alias terms of the short-range fold
  bool remainder_zero = false;      ///< R vanished: Love's coefficients only
  double lattice_entries = 0.0;     ///< of the short-range fold
  /// Whether that lattice fits the kernel's limit (2^27 entries): split_frf_kernel refuses a
  /// plan that does not, and the automatic choice does not choose it.
  bool lattice_fits = true;
};
SplitKernelWork split_frf_kernel_work(const Grid& grid, const Frf& frf,
                                      const SplitKernelOptions& options = {});

namespace detail {
/// \iint over the dx x dy rectangle centred at the origin of 1/sqrt((x - x')^2 + (y - y')^2 +
/// beta^2) dx' dy' [m], beta > 0 [m]: the 4-corner sum of F(X, Y) = X asinh(Y/sqrt(X^2 + beta^2))
/// + Y asinh(X/sqrt(Y^2 + beta^2)) - beta atan(X Y/(beta sqrt(X^2 + Y^2 + beta^2))), for which
/// d^2F/dXdY = 1/sqrt(X^2 + Y^2 + beta^2).
double split_rectangle_integral(double x, double y, double dx, double dy, double beta);
}  // namespace detail

}  // namespace coatfft
