#include "surfaces/roughness.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

double rms_height(const Field& heights) {
  COATFFT_REQUIRE(heights.size() > 0, "rms_height: no heights");
  return std::sqrt((heights - heights.mean()).square().mean());
}

namespace {
// The mean squared difference along one axis over `spacing`: n - 1 pairs a line, or n with the
// pair across the edge of a periodic map.
double mean_squared_difference(const Field& z, bool along_x, double spacing, bool periodic) {
  const Eigen::Index n = along_x ? z.rows() : z.cols();
  const Eigen::Index pairs = periodic ? n : n - 1;
  double sum = 0.0;
  for (Eigen::Index k = 0; k < pairs; ++k) {
    const Eigen::Index next = (k + 1) % n;
    const auto d =
        along_x ? (z.row(next) - z.row(k)).eval() : (z.col(next) - z.col(k)).transpose().eval();
    sum += d.square().sum();
  }
  const double count = static_cast<double>(pairs) * static_cast<double>(z.size() / n);
  return sum / count / (spacing * spacing);
}
}  // namespace

double rms_slope(const Grid& grid, const Field& heights, bool periodic) {
  COATFFT_REQUIRE(heights.rows() == grid.nx() && heights.cols() == grid.ny(),
                  "rms_slope: the heights are not of the grid's shape");
  COATFFT_REQUIRE(grid.nx() >= 2 && grid.ny() >= 2, "rms_slope: needs at least 2 x 2 points");
  return std::sqrt(mean_squared_difference(heights, true, grid.dx(), periodic) +
                   mean_squared_difference(heights, false, grid.dy(), periodic));
}

}  // namespace coatfft

namespace coatfft {

EdgeMismatch edge_mismatch(const Field& z) {
  const Eigen::Index nx = z.rows(), ny = z.cols();
  COATFFT_REQUIRE(nx >= 2 && ny >= 2, "edge_mismatch: needs at least 2 x 2 points");
  const double jumps =
      (z.row(0) - z.row(nx - 1)).square().sum() + (z.col(0) - z.col(ny - 1)).square().sum();
  const double steps = (z.bottomRows(nx - 1) - z.topRows(nx - 1)).square().sum() +
                       (z.rightCols(ny - 1) - z.leftCols(ny - 1)).square().sum();
  const auto n_jumps = static_cast<double>(nx + ny);
  const auto n_steps = static_cast<double>((nx - 1) * ny + nx * (ny - 1));
  return {std::sqrt(jumps / n_jumps), std::sqrt(steps / n_steps)};
}

}  // namespace coatfft
