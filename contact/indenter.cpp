#include "contact/indenter.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace coatfft {

namespace {

void require_length(double value, const char* what) {
  COATFFT_REQUIRE(std::isfinite(value) && value > 0, what, " = ", value,
                  " m, but it must be finite and > 0");
}

// h(i, j - y0) = f(x_i, y_j) on the rows y0 <= j < y0 + rows.
template <typename F>
Field sample(const Grid& grid, std::ptrdiff_t y0, std::ptrdiff_t rows, F&& f) {
  Field h(grid.nx(), rows);
  for (std::ptrdiff_t j = 0; j < rows; ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) h(i, j) = f(grid.x(i), grid.y(y0 + j));
  }
  return h;
}

}  // namespace

void check_indenter(const Grid& grid, const Sphere& sphere) {
  const double R = sphere.radius;
  require_length(R, "Sphere: radius");
  // The farthest cell centre is a corner centre; beyond r = R the sphere has no lower surface.
  const double r_max = std::hypot(grid.x(0), grid.y(0));
  COATFFT_REQUIRE(r_max < R, "Sphere: radius = ", R,
                  " m, but the grid's farthest cell centre lies at r = ", r_max,
                  " m; the exact sphere needs R > r everywhere (enlarge R, shrink the domain, or "
                  "use a Paraboloid)");
}

void check_indenter(const Grid&, const Paraboloid& paraboloid) {
  require_length(paraboloid.radius, "Paraboloid: radius");
}

void check_indenter(const Grid&, const Cylinder& cylinder) {
  require_length(cylinder.radius, "Cylinder: radius");
  require_length(cylinder.end_radius, "Cylinder: end_radius");
  COATFFT_REQUIRE(std::isfinite(cylinder.flat_length) && cylinder.flat_length >= 0,
                  "Cylinder: flat_length = ", cylinder.flat_length,
                  " m, but it must be finite and >= 0");
}

void check_indenter(const Grid&, const FlatPunch& punch) {
  require_length(punch.radius, "FlatPunch: radius");
  require_length(punch.edge_radius, "FlatPunch: edge_radius");
}

void check_indenter(const Grid& grid, const HeightMap& map) {
  COATFFT_REQUIRE(map.heights.rows() == grid.nx() && map.heights.cols() == grid.ny(),
                  "HeightMap: shape (", map.heights.rows(), ", ", map.heights.cols(),
                  "), but the grid needs (nx, ny) = (", grid.nx(), ", ", grid.ny(), ")");
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      COATFFT_REQUIRE(std::isfinite(map.heights(i, j)), "HeightMap: h(", i, ", ", j,
                      ") = ", map.heights(i, j), ", but every height must be finite");
    }
  }
}

void check_indenter(const Grid& grid, const Indenter& indenter) {
  std::visit([&grid](const auto& shape) { check_indenter(grid, shape); }, indenter);
}

namespace {

// The separation h(x, y) of each analytic shape, its parameters checked by check_indenter.
auto profile(const Sphere& sphere) {
  const double R = sphere.radius;
  // R - sqrt(R^2 - r^2) rewritten as r^2 / (R + sqrt(R^2 - r^2)): no cancellation for r << R.
  return [R](double x, double y) {
    const double r2 = x * x + y * y;
    return r2 / (R + std::sqrt(R * R - r2));
  };
}

auto profile(const Paraboloid& paraboloid) {
  const double R = paraboloid.radius;
  return [R](double x, double y) { return (x * x + y * y) / (2.0 * R); };
}

auto profile(const Cylinder& cylinder) {
  const double R = cylinder.radius;
  const double L = cylinder.flat_length;
  const double Re = cylinder.end_radius;
  return [=](double x, double y) {
    const double s = std::max(std::abs(x) - 0.5 * L, 0.0);
    return y * y / (2.0 * R) + s * s / (2.0 * Re);
  };
}

auto profile(const FlatPunch& punch) {
  const double a = punch.radius;
  const double rho = punch.edge_radius;
  return [=](double x, double y) {
    const double s = std::max(std::hypot(x, y) - a, 0.0);
    return s * s / (2.0 * rho);
  };
}

// The checked shape on the rows y0 <= j < y0 + rows.
template <typename Shape>
Field sampled(const Grid& grid, const Shape& shape, std::ptrdiff_t y0, std::ptrdiff_t rows) {
  check_indenter(grid, shape);
  return sample(grid, y0, rows, profile(shape));
}
Field sampled(const Grid& grid, const HeightMap& map, std::ptrdiff_t y0, std::ptrdiff_t rows) {
  check_indenter(grid, map);
  return map.heights.middleCols(y0, rows);
}

}  // namespace

Field height(const Grid& grid, const Sphere& sphere) {
  return sampled(grid, sphere, 0, grid.ny());
}
Field height(const Grid& grid, const Paraboloid& paraboloid) {
  return sampled(grid, paraboloid, 0, grid.ny());
}
Field height(const Grid& grid, const Cylinder& cylinder) {
  return sampled(grid, cylinder, 0, grid.ny());
}
Field height(const Grid& grid, const FlatPunch& punch) {
  return sampled(grid, punch, 0, grid.ny());
}

Field height(const Grid& grid, const HeightMap& map) {
  check_indenter(grid, map);
  return map.heights;
}

Field height(const Grid& grid, const Indenter& indenter) {
  return std::visit([&grid](const auto& shape) { return height(grid, shape); }, indenter);
}

Field take_height(const Grid& grid, Indenter& indenter) {
  auto* map = std::get_if<HeightMap>(&indenter);
  if (map == nullptr) return height(grid, indenter);
  check_indenter(grid, *map);
  return std::move(map->heights);
}

Field height_rows(const Grid& grid, const Indenter& indenter, std::ptrdiff_t y0,
                  std::ptrdiff_t rows) {
  detail::require_rows(grid, y0, rows, "height_rows");
  return std::visit([&](const auto& shape) { return sampled(grid, shape, y0, rows); }, indenter);
}

std::optional<double> ball_radius(const Indenter& indenter) {
  if (const auto* s = std::get_if<Sphere>(&indenter)) return s->radius;
  if (const auto* p = std::get_if<Paraboloid>(&indenter)) return p->radius;
  return std::nullopt;
}

bool is_axisymmetric(const Indenter& indenter) {
  if (const auto* cylinder = std::get_if<Cylinder>(&indenter)) {
    return cylinder->flat_length == 0 && cylinder->end_radius == cylinder->radius;
  }
  return !std::holds_alternative<HeightMap>(indenter);
}

}  // namespace coatfft
