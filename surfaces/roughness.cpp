#include "surfaces/roughness.hpp"

#include <cmath>

#include "core/error.hpp"

namespace coatfft {

namespace {
// A power of two near the largest |z| (1 for a flat zero map): dividing by it is exact, and it
// keeps the sums and squares below finite whenever the parameter itself is (heights of 1e200 m
// square to infinity otherwise).
double magnitude_scale(const Field& z) {
  const double largest = z.abs().maxCoeff();
  return largest > 0 && std::isfinite(largest) ? std::exp2(std::ilogb(largest)) : 1.0;
}
}  // namespace

double rms_height(const Field& heights) {
  COATFFT_REQUIRE(heights.size() > 0, "rms_height: no heights");
  const double scale = magnitude_scale(heights);
  const Field z = heights / scale;
  return scale * std::sqrt((z - z.mean()).square().mean());
}

namespace {
// The mean squared difference along one axis: n - 1 pairs a line, or n with the pair across the
// edge of a periodic map.
double mean_squared_difference(const Field& z, bool along_x, bool periodic) {
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
  return sum / count;
}
}  // namespace

double rms_slope(const Grid& grid, const Field& heights, bool periodic) {
  COATFFT_REQUIRE(heights.rows() == grid.nx() && heights.cols() == grid.ny(),
                  "rms_slope: the heights are not of the grid's shape");
  COATFFT_REQUIRE(grid.nx() >= 2 && grid.ny() >= 2, "rms_slope: needs at least 2 x 2 points");
  const double scale = magnitude_scale(heights);
  const Field z = heights / scale;
  return scale * std::hypot(std::sqrt(mean_squared_difference(z, true, periodic)) / grid.dx(),
                            std::sqrt(mean_squared_difference(z, false, periodic)) / grid.dy());
}

}  // namespace coatfft

namespace coatfft {

EdgeMismatch edge_mismatch(const Field& heights) {
  const Eigen::Index nx = heights.rows(), ny = heights.cols();
  COATFFT_REQUIRE(nx >= 2 && ny >= 2, "edge_mismatch: needs at least 2 x 2 points");
  const double scale = magnitude_scale(heights);
  const Field z = heights / scale;
  const double jumps =
      (z.row(0) - z.row(nx - 1)).square().sum() + (z.col(0) - z.col(ny - 1)).square().sum();
  const double steps = (z.bottomRows(nx - 1) - z.topRows(nx - 1)).square().sum() +
                       (z.rightCols(ny - 1) - z.leftCols(ny - 1)).square().sum();
  const auto n_jumps = static_cast<double>(nx + ny);
  const auto n_steps = static_cast<double>((nx - 1) * ny + nx * (ny - 1));
  return {scale * std::sqrt(jumps / n_jumps), scale * std::sqrt(steps / n_steps)};
}

}  // namespace coatfft
