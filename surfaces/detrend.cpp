#include "surfaces/detrend.hpp"

#include <string>

#include "core/error.hpp"

namespace coatfft {

Detrend detrend_from_name(std::string_view name, std::string_view what) {
  if (name == "none") return Detrend::none;
  if (name == "mean") return Detrend::mean;
  if (name == "plane") return Detrend::plane;
  throw InvalidArgument(std::string(what) + " = \"" + std::string(name) +
                        "\" is not one of \"none\", \"mean\", \"plane\"");
}

Field detrended(const Grid& grid, const Field& heights, Detrend detrend) {
  COATFFT_REQUIRE(heights.rows() == grid.nx() && heights.cols() == grid.ny(),
                  "detrended: the heights are not of the grid's shape");
  if (detrend == Detrend::none) return heights;
  Field out = heights - heights.mean();
  if (detrend == Detrend::mean) return out;
  // The cell centres are symmetric about the origin, so 1, x and y are orthogonal over the grid:
  // the plane's slopes are sum(x z)/sum(x^2) and sum(y z)/sum(y^2).
  double xz = 0.0, xx = 0.0, yz = 0.0, yy = 0.0;
  for (Eigen::Index j = 0; j < grid.ny(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i) {
      xz += grid.x(i) * out(i, j);
      xx += grid.x(i) * grid.x(i);
      yz += grid.y(j) * out(i, j);
      yy += grid.y(j) * grid.y(j);
    }
  const double b = xx > 0 ? xz / xx : 0.0, c = yy > 0 ? yz / yy : 0.0;
  for (Eigen::Index j = 0; j < grid.ny(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i) out(i, j) -= b * grid.x(i) + c * grid.y(j);
  return out;
}

Field gap_of_topography(const Field& heights) {
  COATFFT_REQUIRE(heights.size() > 0, "gap_of_topography: no heights");
  return heights.maxCoeff() - heights;
}

}  // namespace coatfft
