// Text topographies: a matrix of heights (row j is y_j), or "x y z" rows on a regular grid in any
// order. Both are read by the scene's CSV reader (separators, comments, a byte order mark and
// header lines as it takes them). A .xyz file is x y z rows, checked as such; a .csv, .txt or .asc
// file of three columns is x y z rows when its first two columns take nx and ny distinct values
// with nx ny = rows (nx, ny >= 2) -- a matrix of heights three points wide never does unless its
// heights repeat in that pattern, which a measurement does not -- and a matrix otherwise.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "topography/formats.hpp"

namespace coatfft::topography {

namespace {
using Index = Eigen::Index;

std::vector<double> distinct_values(const Field& rows, Index column) {
  std::vector<double> values(rows.row(column).begin(), rows.row(column).end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// The distinct x and y of three-column rows (the Field is (columns, rows)).
struct Coordinates {
  std::vector<double> xs, ys;
  // Whether they make a grid of the rows: nx ny = rows, nx, ny >= 2.
  bool grid(Index rows) const {
    return xs.size() >= 2 && ys.size() >= 2 && static_cast<Index>(xs.size() * ys.size()) == rows;
  }
};

// The spacing of sorted distinct coordinates, which must be uniform: each within 1 % of a
// spacing of its place (files print coordinates with a few digits, so exact equality would
// refuse regular grids; a missing line of points is 100 % off).
double uniform_spacing(const std::filesystem::path& path, const std::vector<double>& values,
                       const char* axis) {
  const double spacing = (values.back() - values.front()) / static_cast<double>(values.size() - 1);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double expected = values.front() + spacing * static_cast<double>(k);
    COATFFT_REQUIRE(std::abs(values[k] - expected) <= 0.01 * spacing, path.string(),
                    ": x y z rows: the ", axis, " coordinates are not uniformly spaced (", axis,
                    " = ", values[k], " where the ", values.size(), " values from ", values.front(),
                    " to ", values.back(), " put ", expected, ")");
  }
  return spacing;
}

Topography xyz_topography(const std::filesystem::path& path, const Field& rows,
                          const Coordinates& c) {
  const std::vector<double>& xs = c.xs;
  const std::vector<double>& ys = c.ys;
  COATFFT_REQUIRE(c.grid(rows.cols()), path.string(), ": x y z rows: ", rows.cols(), " rows on ",
                  xs.size(), " x values and ", ys.size(),
                  " y values do not make a regular grid (one row a point)");
  const double dx = uniform_spacing(path, xs, "x"), dy = uniform_spacing(path, ys, "y");
  const auto nx = static_cast<Index>(xs.size()), ny = static_cast<Index>(ys.size());
  Topography topography;
  topography.heights = Field::Constant(nx, ny, std::nan(""));
  std::vector<bool> seen(static_cast<std::size_t>(nx * ny), false);
  for (Index r = 0; r < rows.cols(); ++r) {
    const auto i = static_cast<Index>(std::lround((rows(0, r) - xs.front()) / dx));
    const auto j = static_cast<Index>(std::lround((rows(1, r) - ys.front()) / dy));
    COATFFT_REQUIRE(!seen[static_cast<std::size_t>(i + nx * j)], path.string(),
                    ": x y z rows: the point x = ", rows(0, r), ", y = ", rows(1, r),
                    " is given twice");
    seen[static_cast<std::size_t>(i + nx * j)] = true;
    topography.heights(i, j) = rows(2, r);
  }
  topography.lx = dx * static_cast<double>(nx);
  topography.ly = dy * static_cast<double>(ny);
  topography.format = "xyz";
  return topography;
}
}  // namespace

Topography read_text_topography(const std::filesystem::path& path, const ReadOptions& options,
                                bool xyz) {
  const Field matrix = io::read_csv_matrix(path, options.max_bytes);
  COATFFT_REQUIRE(!xyz || matrix.rows() == 3, path.string(),
                  ": x y z rows need three columns, not ", matrix.rows());
  if (matrix.rows() == 3) {
    const Coordinates c{distinct_values(matrix, 0), distinct_values(matrix, 1)};
    if (xyz || c.grid(matrix.cols())) return xyz_topography(path, matrix, c);
  }
  Topography topography;
  topography.heights = matrix;
  topography.format = "csv";
  return topography;
}

}  // namespace coatfft::topography
