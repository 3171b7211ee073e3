#include "loads/discretization_error.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"

namespace coatfft {
namespace {

// Factors of docs/theory.md 4.7, (L1)-(L2). With centre sampling, op(p_centre - p_average) is
// exactly E_centre - E_average (the two sampling errors), which underestimates E_centre where the
// smaller E_average points the same way: by up to 7 % measured, hence 1.1. The coarse-grid
// difference of cell averages measured 2.8 to 6.7 times the true error (3.4 and up from 4 cells
// per load radius), hence 1/3.
constexpr double centre_factor = 1.1;
constexpr double coarse_factor = 1.0 / 3.0;

// p averaged over blocks of 2 x 2 cells, the blocks starting at cell (0, 0); a last odd row or
// column forms blocks of its own. The result is the cell-average sampling of a grid twice as
// coarse (when p is itself cell-averaged), written back onto the fine cells, so that the fine
// operator computes that coarse load's displacement exactly at the fine centres.
Field block_average(const Field& p) {
  Field out(p.rows(), p.cols());
  for (Eigen::Index j0 = 0; j0 < p.cols(); j0 += 2)
    for (Eigen::Index i0 = 0; i0 < p.rows(); i0 += 2) {
      const Eigen::Index wi = std::min<Eigen::Index>(2, p.rows() - i0);
      const Eigen::Index wj = std::min<Eigen::Index>(2, p.cols() - j0);
      out.block(i0, j0, wi, wj).setConstant(p.block(i0, j0, wi, wj).mean());
    }
  return out;
}

}  // namespace

void check_analytic_load(const AnalyticLoad& load) {
  COATFFT_REQUIRE(
      load.kind == AnalyticLoad::Kind::hertz || load.kind == AnalyticLoad::Kind::uniform_disk,
      "AnalyticLoad: unknown kind ", static_cast<int>(load.kind));
  COATFFT_REQUIRE(std::isfinite(load.amplitude), "AnalyticLoad: amplitude = ", load.amplitude,
                  " Pa, but it must be finite");
  COATFFT_REQUIRE(std::isfinite(load.radius) && load.radius > 0,
                  "AnalyticLoad: radius = ", load.radius, " m, but it must be finite and > 0");
  COATFFT_REQUIRE(load.sampling == Sampling::centre || load.sampling == Sampling::cell_average,
                  "AnalyticLoad: unknown sampling ", static_cast<int>(load.sampling));
}

Field sample_load(const Grid& grid, const AnalyticLoad& load, Sampling sampling) {
  return sample_load_rows(grid, load, sampling, 0, grid.ny());
}

Field sample_load_rows(const Grid& grid, const AnalyticLoad& load, Sampling sampling,
                       std::ptrdiff_t y0, std::ptrdiff_t rows) {
  check_analytic_load(load);
  switch (load.kind) {
    case AnalyticLoad::Kind::hertz:
      return hertz_pressure_rows(grid, load.amplitude, load.radius, sampling, y0, rows);
    case AnalyticLoad::Kind::uniform_disk:
      return uniform_disk_pressure_rows(grid, load.amplitude, load.radius, sampling, y0, rows);
  }
  throw InvalidArgument("sample_load: unknown load kind");
}

LoadDifference load_discretization_difference(const Grid& grid, const AnalyticLoad& load,
                                              const Field& pressure, std::ptrdiff_t y0) {
  const std::ptrdiff_t rows = pressure.cols();
  // A slab without rows (a rank's, in a distributed run) has no difference to sample rows for.
  if (rows == 0)
    return {Field(pressure.rows(), 0),
            load.sampling == Sampling::centre ? centre_factor : coarse_factor};
  if (load.sampling == Sampling::centre)
    return {pressure - sample_load_rows(grid, load, Sampling::cell_average, y0, rows),
            centre_factor};
  // The blocks start on even rows: the rows' first may pair with the row before, their last with
  // the row after (unless it is the grid's last).
  const std::ptrdiff_t before = y0 % 2, after = (y0 + rows) % 2 == 1 && y0 + rows < grid.ny();
  Field blocks(pressure.rows(), before + rows + after);
  if (before) blocks.col(0) = sample_load_rows(grid, load, load.sampling, y0 - 1, 1).col(0);
  blocks.middleCols(before, rows) = pressure;
  if (after)
    blocks.col(before + rows) = sample_load_rows(grid, load, load.sampling, y0 + rows, 1).col(0);
  return {block_average(blocks).middleCols(before, rows) - pressure, coarse_factor};
}

LoadDiscretizationEstimate estimate_load_discretization_error(SurfaceOperator& op,
                                                              const AnalyticLoad& load,
                                                              double max_abs_displacement) {
  const Field pressure = sample_load(op.grid(), load, load.sampling);
  return estimate_load_discretization_error(op, load, pressure, max_abs_displacement);
}

LoadDiscretizationEstimate estimate_load_discretization_error(SurfaceOperator& op,
                                                              const AnalyticLoad& load,
                                                              const Field& pressure,
                                                              double max_abs_displacement) {
  check_analytic_load(load);
  const Grid& grid = op.grid();
  COATFFT_REQUIRE(pressure.rows() == grid.nx() && pressure.cols() == grid.ny(),
                  "estimate_load_discretization_error: the pressure has shape (", pressure.rows(),
                  ", ", pressure.cols(), "), but the operator's grid has (", grid.nx(), ", ",
                  grid.ny(), ")");
  const LoadDifference d = load_discretization_difference(grid, load, pressure, 0);
  return load_discretization_estimate(d, op.apply(d.difference).abs().maxCoeff(),
                                      max_abs_displacement);
}

LoadDiscretizationEstimate load_discretization_estimate(const LoadDifference& d,
                                                        double max_abs_difference_displacement,
                                                        double max_abs_displacement) {
  COATFFT_REQUIRE(std::isfinite(max_abs_displacement) && max_abs_displacement > 0,
                  "estimate_load_discretization_error: max |u| = ", max_abs_displacement,
                  " m, but it must be finite and > 0");
  LoadDiscretizationEstimate estimate;
  estimate.absolute_error = d.factor * max_abs_difference_displacement;
  estimate.relative_error = estimate.absolute_error / max_abs_displacement;
  return estimate;
}

}  // namespace coatfft
