#pragma once
// A uniform grid of nx x ny rectangular cells covering [-lx/2, lx/2] x [-ly/2, ly/2] (metres).
#include <cstddef>
#include <string_view>

namespace coatfft {

class Grid {
 public:
  /// Validates on construction: nx, ny in [1, max_cells_per_axis] and lx, ly in
  /// [min_length, max_length] (throws InvalidArgument).
  Grid(std::ptrdiff_t nx, std::ptrdiff_t ny, double lx, double ly);

  /// Bounds of lx and ly [m]: any unit system from femtometres to light years fits, and the
  /// kernels' products of lengths cannot overflow or underflow double precision.
  static constexpr double min_length = 1e-100;
  static constexpr double max_length = 1e100;
  /// Cells along one axis at most: 65536^2 cells take 32 GiB per field, and the padded transform
  /// of a free boundary four times that; beyond it, sizes are typing errors, and nx * ny could
  /// overflow before any memory estimate sees it.
  static constexpr std::ptrdiff_t max_cells_per_axis = 65536;

  std::ptrdiff_t nx() const { return nx_; }
  std::ptrdiff_t ny() const { return ny_; }
  double lx() const { return lx_; }                             ///< domain length along x [m]
  double ly() const { return ly_; }                             ///< domain length along y [m]
  double dx() const { return lx_ / static_cast<double>(nx_); }  ///< cell size along x [m]
  double dy() const { return ly_ / static_cast<double>(ny_); }  ///< cell size along y [m]
  std::ptrdiff_t nb_cells() const { return nx_ * ny_; }
  /// Cell centre x_i = -lx/2 + (i + 1/2) dx [m].
  double x(std::ptrdiff_t i) const { return -0.5 * lx_ + (static_cast<double>(i) + 0.5) * dx(); }
  /// Cell centre y_j = -ly/2 + (j + 1/2) dy [m].
  double y(std::ptrdiff_t j) const { return -0.5 * ly_ + (static_cast<double>(j) + 0.5) * dy(); }
  /// Indices of the cell whose centre is nearest the origin; for an even count the two middle
  /// cells tie and the lower index (centre at -d/2) is taken.
  std::ptrdiff_t centre_i() const { return (nx_ - 1) / 2; }
  std::ptrdiff_t centre_j() const { return (ny_ - 1) / 2; }

  bool operator==(const Grid&) const = default;

 private:
  std::ptrdiff_t nx_;
  std::ptrdiff_t ny_;
  double lx_;
  double ly_;
};

/// Refuses the radius [m] of a load centred on `grid` that the grid cannot hold: not finite,
/// <= 0, or more than half the shorter side of the domain (the load would not fit; a radius in
/// other units, metres taken for millimetres, lands here). Throws InvalidArgument naming `key`
/// ("[pressure] a", "make_operator: load_radius"). A radius narrower than a cell is the caller's
/// to judge: cell averages keep its force, centre samples do not.
void require_load_radius(const Grid& grid, double radius, std::string_view key);

namespace detail {
/// Refuses rows [y0, y0 + rows) that are not rows of `grid` (a slab's sampling functions), naming
/// `who`. Throws InvalidArgument.
void require_rows(const Grid& grid, std::ptrdiff_t y0, std::ptrdiff_t rows, std::string_view who);
}  // namespace detail

}  // namespace coatfft
