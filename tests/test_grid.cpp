#include <catch2/catch.hpp>
#include <limits>

#include "core/error.hpp"
#include "core/grid.hpp"

using coatfft::Grid;
using coatfft::InvalidArgument;

TEST_CASE("Grid cell centres are symmetric about the origin", "[grid]") {
  const Grid g(4, 3, 2.0, 3.0);
  CHECK(g.dx() == 0.5);
  CHECK(g.dy() == 1.0);
  CHECK(g.x(0) == -0.75);
  CHECK(g.x(3) == 0.75);
  CHECK(g.y(0) == -1.0);
  CHECK(g.y(1) == 0.0);  // odd ny: a centre on the origin
  CHECK(g.nb_cells() == 12);
}

TEST_CASE("Grid refuses bad sizes with a message naming the value", "[grid][bad_input]") {
  CHECK_THROWS_WITH(Grid(0, 3, 1.0, 1.0), Catch::Contains("nx = 0"));
  CHECK_THROWS_WITH(Grid(3, -1, 1.0, 1.0), Catch::Contains("ny = -1"));
  // One limit per axis for every front end: at the limit the grid is built (no memory is
  // allocated by a Grid), one beyond it is refused, even where nx * ny would overflow.
  CHECK_NOTHROW(Grid(Grid::max_cells_per_axis, Grid::max_cells_per_axis, 1.0, 1.0));
  CHECK_THROWS_WITH(Grid(Grid::max_cells_per_axis + 1, 3, 1.0, 1.0),
                    Catch::Contains("nx = 65537, but nx must be in [1, 65536]"));
  CHECK_THROWS_WITH(Grid(3, std::ptrdiff_t(1) << 40, 1.0, 1.0),
                    Catch::Contains("ny = 1099511627776"));
  CHECK_THROWS_AS(Grid(3, 3, 0.0, 1.0), InvalidArgument);
  CHECK_THROWS_AS(Grid(3, 3, 1.0, std::numeric_limits<double>::infinity()), InvalidArgument);
  CHECK_THROWS_AS(Grid(3, 3, std::numeric_limits<double>::quiet_NaN(), 1.0), InvalidArgument);
}

TEST_CASE("a load radius the grid cannot hold is refused, naming its key", "[grid][bad_input]") {
  const Grid g(64, 32, 64e-6, 32e-6);  // 1 um cells, 16 um half of the shorter side
  CHECK_NOTHROW(coatfft::require_load_radius(g, 16e-6, "load_radius"));
  CHECK_NOTHROW(coatfft::require_load_radius(g, 1e-9, "load_radius"));  // narrower: caller's call
  // 200 m on a micrometre grid: metres for micrometres, refused before anything is computed.
  for (const double radius :
       {200.0, 16.001e-6, 0.0, -1e-6, std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity()}) {
    INFO(radius);
    CHECK_THROWS_WITH(coatfft::require_load_radius(g, radius, "make_operator: load_radius"),
                      Catch::Contains("make_operator: load_radius = ") &&
                          Catch::Contains("at most half the domain (1.6e-05 m)"));
    CHECK_THROWS_AS(coatfft::require_load_radius(g, radius, "load_radius"), InvalidArgument);
  }
}
