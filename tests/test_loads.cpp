#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "core/grid.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/load_limits.hpp"
#include "loads/uniform_disk_pressure.hpp"

using namespace coatfft;
using std::numbers::pi;

namespace {

double total_load(const Field& p, const Grid& g) {
  return p.sum() * g.dx() * g.dy();
}

// Mean of the fine cell averages over each coarse cell (fine grid = coarse refined r x r).
Field coarsen(const Field& fine, std::ptrdiff_t r) {
  Field out = Field::Zero(fine.rows() / r, fine.cols() / r);
  for (std::ptrdiff_t j = 0; j < fine.cols(); ++j)
    for (std::ptrdiff_t i = 0; i < fine.rows(); ++i) out(i / r, j / r) += fine(i, j);
  return out / static_cast<double>(r * r);
}

}  // namespace

TEST_CASE("Cell-averaged loads carry exactly the continuous total load", "[loads]") {
  const double a = 1e-3, p0 = 1e9;
  // Odd, even, non-square cells and a grid whose cells are cut in many ways; every grid covers
  // the circle. Tolerance 1e-12: the disk is closed form (round-off ~1e-15 per cell) and the
  // Hertz x-quadrature runs at 1e-14 relative per cell; summing ~1e3 cells adds round-off only.
  const auto [nx, ny, lx, ly] =
      GENERATE(table<std::ptrdiff_t, std::ptrdiff_t, double, double>({{64, 64, 3e-3, 3e-3},
                                                                      {33, 33, 2.2e-3, 2.2e-3},
                                                                      {17, 40, 2.5e-3, 3.1e-3},
                                                                      {2, 2, 2e-3, 2e-3},
                                                                      {1, 1, 3e-3, 3e-3},
                                                                      {7, 3, 2.0001e-3, 2.5e-3}}));
  const Grid g(nx, ny, lx, ly);
  CHECK(total_load(hertz_pressure(g, p0, a, Sampling::cell_average), g) ==
        Approx(2.0 / 3.0 * pi * a * a * p0).epsilon(1e-12));
  CHECK(total_load(uniform_disk_pressure(g, p0, a, Sampling::cell_average), g) ==
        Approx(pi * a * a * p0).epsilon(1e-12));
}

TEST_CASE("Cell averages are additive: a coarse cell is the mean of its sub-cells", "[loads]") {
  // Independent of the total-load identity: the sub-cells are cut by the circle at different
  // places (different quadrature pieces), yet their mean must equal the coarse value. Tolerance
  // 1e-12 of p0 for the same reason as above.
  const double a = 1.0, p0 = 1.0;
  const Grid coarse(9, 7, 2.6, 2.3), fine(27, 21, 2.6, 2.3);
  for (const bool hertz : {true, false}) {
    const Field c = hertz ? hertz_pressure(coarse, p0, a, Sampling::cell_average)
                          : uniform_disk_pressure(coarse, p0, a, Sampling::cell_average);
    const Field f = hertz ? hertz_pressure(fine, p0, a, Sampling::cell_average)
                          : uniform_disk_pressure(fine, p0, a, Sampling::cell_average);
    CHECK((coarsen(f, 3) - c).abs().maxCoeff() < 1e-12);
  }
}

TEST_CASE("A cut cell matches brute-force sub-sampling", "[loads]") {
  // One cell straddling the circle, compared with the midpoint rule on 2000 x 2000 sub-cells.
  // The midpoint rule on a discontinuous (disk) or sqrt-edged (Hertz) integrand converges like
  // O(h) resp. O(h^1.5) along the cut, so we allow 1e-4 relative; the point is a gross check of
  // geometry (which side, which part of the cell), the exactness is tested above.
  const double a = 1.0;
  const Grid g(5, 5, 2.5, 2.5);  // cell (4, 2): x in [0.75, 1.25], y in [-0.25, 0.25]
  const Field ph = hertz_pressure(g, 1.0, a, Sampling::cell_average);
  const Field pd = uniform_disk_pressure(g, 1.0, a, Sampling::cell_average);
  const int n = 2000;
  double sh = 0.0, sd = 0.0;
  for (int jj = 0; jj < n; ++jj)
    for (int ii = 0; ii < n; ++ii) {
      const double x = 0.75 + (ii + 0.5) * 0.5 / n, y = -0.25 + (jj + 0.5) * 0.5 / n;
      const double s = 1.0 - x * x - y * y;
      if (s > 0) {
        sh += std::sqrt(s);
        sd += 1.0;
      }
    }
  sh /= double(n) * n;
  sd /= double(n) * n;
  CHECK(ph(4, 2) == Approx(sh).epsilon(1e-4));
  CHECK(pd(4, 2) == Approx(sd).epsilon(1e-4));
  CHECK(pd(2, 2) == 1.0);  // interior cell: exactly p
  CHECK(ph(0, 0) == 0.0);  // corner cell outside the circle
}

TEST_CASE("Centre-sampled loads converge to the total load with N", "[loads]") {
  const double a = 1e-3, p0 = 2e9, L = 3e-3;
  const double hertz_total = 2.0 / 3.0 * pi * a * a * p0, disk_total = pi * a * a * p0;
  double prev_h = 1.0, prev_d = 1.0;
  for (const std::ptrdiff_t n : {16, 64, 256}) {
    const Grid g(n, n, L, L);
    const double eh =
        std::abs(total_load(hertz_pressure(g, p0, a, Sampling::centre), g) / hertz_total - 1.0);
    const double ed = std::abs(
        total_load(uniform_disk_pressure(g, p0, a, Sampling::centre), g) / disk_total - 1.0);
    // Centre sampling of a load with a sqrt edge (Hertz) or a jump (disk): the error is
    // dominated by the cut cells, O(dx^1.5) resp. O(dx) on average but erratic (lattice-point
    // counting), so we only require a decrease by 4x per 4x refinement and a small final error.
    CHECK(eh < prev_h / 4.0);
    if (n > 16) CHECK(ed < prev_d);
    prev_h = eh;
    prev_d = ed;
  }
  CHECK(prev_h < 1e-3);
  CHECK(prev_d < 1e-2);
  // Centre values: an odd grid has a cell centred on the origin, where p = p0 exactly.
  const Grid odd(5, 5, L, L);
  CHECK(hertz_pressure(odd, p0, a, Sampling::centre)(2, 2) == p0);
  const double x = odd.x(3);  // 0.6 a: p0 sqrt(1 - 0.36) = 0.8 p0
  CHECK(hertz_pressure(odd, p0, a, Sampling::centre)(3, 2) ==
        Approx(p0 * std::sqrt(1.0 - (x / a) * (x / a))).epsilon(1e-15));
}

TEST_CASE("Loads refuse bad radii and pressures", "[loads][bad_input]") {
  const Grid g(4, 4, 1.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(hertz_pressure(g, 1.0, 0.0, Sampling::centre), Catch::Contains("a = 0"));
  CHECK_THROWS_AS(hertz_pressure(g, nan, 1.0, Sampling::centre), InvalidArgument);
  CHECK_THROWS_WITH(uniform_disk_pressure(g, 1.0, -1.0, Sampling::cell_average),
                    Catch::Contains("a = -1"));
  CHECK_THROWS_AS(uniform_disk_pressure(g, 1.0, nan, Sampling::centre), InvalidArgument);
}

TEST_CASE("One set of disk-load limits for every front end", "[loads][bad_input]") {
  const Grid g(64, 32, 1e-3, 0.5e-3);  // dx = dy = 15.6 um; half the domain 0.25 mm
  const DiskLoadKeys keys{"p0", "a", "the grid"};
  const auto refused = [&](double amplitude, double radius, Sampling s, const char* why) {
    CHECK_THROWS_WITH(require_disk_load(g, amplitude, radius, s, keys), Catch::Contains(why));
  };
  CHECK_NOTHROW(require_disk_load(g, 1e9, 0.1e-3, Sampling::centre, keys));
  refused(-1e9, 0.1e-3, Sampling::centre, "p0 = -1e+09 Pa must be finite and > 0");
  refused(0.0, 0.1e-3, Sampling::centre, "p0 = 0 Pa");
  refused(std::numeric_limits<double>::infinity(), 0.1e-3, Sampling::centre, "p0 = inf");
  refused(1e9, 0.26e-3, Sampling::cell_average, "at most half the domain (0.00025 m)");
  // A disk 0.4 cells wide: centre sampling misses or overfills; cell averages keep its force.
  const double narrow = 0.2 * g.dx();
  refused(1e9, narrow, Sampling::centre,
          "narrower than a cell (dx = 1.5625e-05 m, dy = 1.5625e-05 m from the grid)");
  CHECK_NOTHROW(require_disk_load(g, 1e9, narrow, Sampling::cell_average, keys));
  CHECK_NOTHROW(require_disk_load(g, 1e9, 0.5 * g.dx(), Sampling::centre, keys));
}
