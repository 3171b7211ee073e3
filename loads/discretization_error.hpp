#pragma once
// The error of the piecewise-constant load: an operator turns cell values of the pressure into
// displacements, so the displacement of a continuous analytic load (Hertz, uniform disk) is
// computed as that of its cell-wise samples. This estimates how far the two differ, with the
// scene's own operator (docs/theory.md 4.7).
#include "../convolution/operators/surface_operator.hpp"
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "sampling.hpp"

namespace coatfft {

/// A continuous axisymmetric pressure centred on the grid origin, and how it is sampled: what a
/// scene's [pressure] section with kind = "hertz" or "uniform_disk" describes.
struct AnalyticLoad {
  enum class Kind {
    hertz,         ///< p = amplitude sqrt(1 - r^2/a^2) on r < a (loads/hertz_pressure.hpp)
    uniform_disk,  ///< p = amplitude on r < a (loads/uniform_disk_pressure.hpp)
  };
  Kind kind = Kind::hertz;
  double amplitude = 0.0;  ///< p0 of Hertz, p of the uniform disk [Pa], finite
  double radius = 0.0;     ///< load radius a [m], finite and > 0
  Sampling sampling = Sampling::centre;
};

/// Throws InvalidArgument, naming the field, unless `load` is usable: a known kind and sampling,
/// a finite amplitude, a finite radius > 0.
void check_analytic_load(const AnalyticLoad& load);

/// The cell values of `load` on `grid` with `sampling` (which may differ from load.sampling):
/// hertz_pressure or uniform_disk_pressure. Throws InvalidArgument on a bad amplitude or radius.
Field sample_load(const Grid& grid, const AnalyticLoad& load, Sampling sampling);

/// Rows [y0, y0 + rows) of sample_load(grid, load, sampling): a distributed rank's slab.
Field sample_load_rows(const Grid& grid, const AnalyticLoad& load, Sampling sampling,
                       std::ptrdiff_t y0, std::ptrdiff_t rows);

/// The load difference whose displacement, times `factor`, estimates the error of the cell-wise
/// load (docs/theory.md 4.7): with centre sampling p_centre - p_average, with cell averages the
/// averages over 2 x 2 blocks (from cell (0, 0)) less p. On rows [y0, y0 + pressure.cols()) of
/// `grid`, `pressure` those rows of `load` as sampled; a block that reaches a row beyond them
/// samples that row again.
struct LoadDifference {
  Field difference;
  double factor = 0.0;
};
LoadDifference load_discretization_difference(const Grid& grid, const AnalyticLoad& load,
                                              const Field& pressure, std::ptrdiff_t y0);

/// Estimated error of the cell-wise load at the cell centres.
struct LoadDiscretizationEstimate {
  double absolute_error = 0.0;  ///< estimated max |u_cellwise - u_continuous| [m]
  double relative_error = 0.0;  ///< the same divided by the computed max |u| [-]
};

/// The estimate of a load difference `d` from the largest displacement its difference makes
/// [m] (over every rank's rows, in a distributed run) and the computed max |u| [m] (finite, > 0).
LoadDiscretizationEstimate load_discretization_estimate(const LoadDifference& d,
                                                        double max_abs_difference_displacement,
                                                        double max_abs_displacement);

/// Estimates max |u_cellwise - u_continuous| / max |u|, where u_cellwise is what `op` computes
/// from the cell values of `load` (sampled with load.sampling), u_continuous the displacement of
/// the continuous load on the same body at the cell centres, and max_abs_displacement the
/// computed max |u| [m] (finite, > 0). One extra application of `op`, on op.grid():
///
/// * Sampling::centre: 1.1 max |op(p_centre - p_average)| / max |u|. An operator exact for
///   piecewise-constant loads turns the difference of the two samplings into the difference of
///   their errors; the centre sampling's error dominates it.
/// * Sampling::cell_average: (1/3) max |op(B p_average - p_average)| / max |u|, B the mean over
///   blocks of 2 x 2 cells (a last odd row or column alone): a Richardson-type difference with the
///   cell averages of a grid twice as coarse, put back on the fine cells.
///
/// Accuracy, estimate / true error (docs/theory.md 4.7). Homogeneous half-space, DC-FFT, against
/// the closed forms of validation/hertz.hpp, on 60 grids per case (4 to 64 cells per load radius,
/// domains 2.2a to 8a, odd and even sizes, cells up to 4:1): Hertz 1.02 to 2.47 (centre), 1.23 to
/// 2.23 (cell average); uniform disk 1.10 to 1.58, 1.16 to 1.95. Coated bodies (PEEK 0.1a and TiN
/// 0.25a on steel, 48^2 and 96^2 cells on [-1.5a, 1.5a]^2) with frf-split, against the Hankel
/// reference: 1.07 to 2.31. Below 4 cells per radius it can fall under 1 (0.95 measured at 2.7).
/// The operator should be exact for cell-wise loads (DC-FFT, direct, frf-split); with
/// frf-spectral at alpha = 2 the estimate moved by at most 5 %, and it never includes the
/// operator's own error (docs/theory.md 4.3-4.6).
///
/// Throws InvalidArgument on a bad load or max_abs_displacement.
LoadDiscretizationEstimate estimate_load_discretization_error(SurfaceOperator& op,
                                                              const AnalyticLoad& load,
                                                              double max_abs_displacement);

/// The same, given `pressure`: the cell values the caller already sampled,
/// sample_load(op.grid(), load, load.sampling), which are then not sampled again (a cell-averaged
/// Hertz load takes 1.4 s on 1024^2 cells, measured). Throws InvalidArgument if its shape is not
/// op.grid()'s.
LoadDiscretizationEstimate estimate_load_discretization_error(SurfaceOperator& op,
                                                              const AnalyticLoad& load,
                                                              const Field& pressure,
                                                              double max_abs_displacement);

}  // namespace coatfft
