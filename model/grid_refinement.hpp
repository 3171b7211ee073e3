#pragma once
// A grid fine enough for a tolerance: the number of cells for which the error of the cell-wise
// load (loads/discretization_error.hpp) stays within its share of a total tolerance, for
// `[grid] refine = "auto"` (docs/theory.md 4.7).
#include <cstddef>
#include <vector>

#include "../core/grid.hpp"
#include "../loads/discretization_error.hpp"

namespace coatfft {

class Frf;

/// One grid the search estimated.
struct GridTrial {
  std::ptrdiff_t nx = 0;
  std::ptrdiff_t ny = 0;
  double estimate = 0.0;  ///< estimated relative load error, times body_factor [-]
};

/// What choose_grid_for_tolerance chose, and why.
struct GridChoice {
  Grid grid;
  double estimate = 0.0;         ///< estimated relative load error on `grid`, times body_factor
  double load_tolerance = 0.0;   ///< the load's share of the tolerance, which `estimate` meets
  std::vector<GridTrial> tried;  ///< every grid estimated, in order (the chosen one included)
};

struct GridRefinementOptions {
  /// Largest number of cells along either axis.
  std::ptrdiff_t max_cells = 4096;
  /// Relative load error on the body / that on a homogeneous half-space (>= the estimates'
  /// ratio; load_error_body_factor); 1 for a homogeneous body. Finite and > 0.
  double body_factor = 1.0;
};

/// The grid of square-as-possible cells on [-lx/2, lx/2] x [-ly/2, ly/2] whose estimated relative
/// load error (estimate_load_discretization_error, on a homogeneous half-space: DC-FFT, exact for
/// cell-wise loads, times options.body_factor) is at most (1 - operator_share) tolerance: the
/// rest of the total `tolerance` (in (0, 1)) is left to the operator (operator_share in [0, 1)).
/// nx and ny are fast FFT sizes 2^a 3^b 5^c 7^d (core/detail/fft_size.hpp), at most
/// options.max_cells; the cells are at most as long along the shorter axis as along the longer one,
/// and at least 4 per load radius. Search: estimates at 8 and 16 cells per radius fit a convergence
/// order that predicts the size; estimates then bracket it between neighbouring fast sizes of the
/// longer axis (the chosen one meets the share, the next coarser one does not, as estimated). Each
/// estimate uses a window of the grid's own cells around the load (at least 1.5 a each side),
/// which gives the same estimate as the whole grid at a cost set by a/dx alone. Typically 4 to 10
/// estimates; measured 0.05 to 0.1 s (tolerance 1e-2) and 0.3 to 0.5 s (1e-3) for a Hertz load on
/// [-1.5a, 1.5a]^2, 4 to 6 s for 1e-4; a centre-sampled uniform disk (first order in dx) needs
/// 320^2 cells for 1e-2 and ~3500^2 for 1e-3 (a minute).
/// Throws InvalidArgument for bad arguments (message naming the value), and for a tolerance that
/// no grid within max_cells reaches: max_cells fails, or the fitted order needs more than twice
/// max_cells (message naming the tolerance, its share and the best estimate).
GridChoice choose_grid_for_tolerance(double lx, double ly, const AnalyticLoad& load,
                                     double tolerance, double operator_share,
                                     const GridRefinementOptions& options = {});

/// A conservative body_factor for a layered body of FRF `frf` under `load`: u0(C) / u0(body),
/// u0 the centre displacement, u0(C) that of a half-space of compliance C = max k H(k) (over c0,
/// c_inf and k a in [1e-3, 1e4]), u0(body) the Hankel reference
/// (validation/hankel_displacement.hpp). Why: the load's error is a cell-scale effect, set by the
/// body's compliance at wavenumbers ~1/dx (at most C), while max |u| is set at the load's scale.
/// Measured (docs/theory.md 4.7, 48^2 and 96^2 cells on [-1.5a, 1.5a]^2): a soft coating (PEEK 0.1a
/// on steel) makes the relative load error 5.7 to 21 times the homogeneous one, and the factor
/// (18.5 Hertz, 21.7 uniform disk) brings the stand-in's estimate / true error from 0.06-0.20
/// to 1.4-3.7; a stiff one (TiN 0.25a on steel) lowers it to 0.58-0.80 times (factor 1.07, 1.05:
/// estimate / true 1.5 to 3.2).
double load_error_body_factor(const Frf& frf, const AnalyticLoad& load);

}  // namespace coatfft
