// Units of length (topography/units.hpp) and the roughness parameters of a sampled map
// (surfaces/roughness.hpp) against closed forms.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "surfaces/roughness.hpp"
#include "topography/topography_summary.hpp"
#include "topography/units.hpp"

using namespace coatfft;
using topography::metres_per_unit;

TEST_CASE("units: symbols and names in metres; unknown ones refused naming them",
          "[topography][units]") {
  CHECK(metres_per_unit("m", "t") == 1.0);
  CHECK(metres_per_unit("mm", "t") == 1e-3);
  for (const char* micro : {"um", "\u00b5m", "\u03bcm", "micrometre", "micron"})
    CHECK(metres_per_unit(micro, "t") == 1e-6);
  CHECK(metres_per_unit("nm", "t") == 1e-9);
  CHECK(metres_per_unit("pm", "t") == 1e-12);
  for (const char* angstrom : {"\u00c5", "\u212b", "A", "angstrom"})
    CHECK(metres_per_unit(angstrom, "t") == 1e-10);
  CHECK_THROWS_WITH(metres_per_unit("inch", "the file's unit"),
                    Catch::Contains("unknown unit \"inch\" in the file's unit"));
  // Symbols are case-sensitive: Mm is a megametre, not a millimetre.
  CHECK_THROWS_AS(metres_per_unit("Mm", "t"), InvalidArgument);
  CHECK_THROWS_AS(metres_per_unit("", "t"), InvalidArgument);
}

TEST_CASE("roughness: rms height and slope of a sampled sine against closed forms",
          "[topography][roughness]") {
  // z = A sin(2 pi m x / L) over n points of spacing d = L/n: rms height A/sqrt(2) (m < n/2),
  // and the differences z(i+1) - z(i) = 2 A sin(pi m/n) cos(...): rms slope
  // sqrt(2) A sin(pi m/n) / d over a period (periodic) -- the exact values of the sampled map.
  for (const auto& [n, m] : {std::pair{16, 1}, std::pair{12, 5}, std::pair{40, 3}}) {
    const double A = 2e-6, L = 1e-3, d = L / n;
    const Grid g(n, 6, L, 6 * d);
    Field z(n, 6);
    for (Eigen::Index j = 0; j < 6; ++j)
      for (Eigen::Index i = 0; i < n; ++i) z(i, j) = A * std::sin(2 * M_PI * m * g.x(i) / L);
    CHECK(rms_height(z) == Approx(A / std::sqrt(2.0)).epsilon(1e-13));
    const double slope = std::sqrt(2.0) * A * std::sin(M_PI * m / n) / d;
    CHECK(rms_slope(g, z, true) == Approx(slope).epsilon(1e-13));
    // Without the pair across the edge: the n - 1 inner differences' mean square.
    double sum = 0;
    for (Eigen::Index i = 0; i + 1 < n; ++i) sum += std::pow((z(i + 1, 0) - z(i, 0)) / d, 2);
    CHECK(rms_slope(g, z, false) == Approx(std::sqrt(sum / (n - 1))).epsilon(1e-13));
  }
  // A plane a x + b y has slope sqrt(a^2 + b^2) with or without the edges' pairs dropped.
  const Grid g(7, 5, 7e-6, 10e-6);
  Field z(7, 5);
  for (Eigen::Index j = 0; j < 5; ++j)
    for (Eigen::Index i = 0; i < 7; ++i) z(i, j) = 0.3 * g.x(i) - 0.4 * g.y(j);
  CHECK(rms_slope(g, z, false) == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("edge mismatch: a ramp's jump across the edge against its closed form",
          "[topography][roughness]") {
  // z = a i along x: steps a between x neighbours (and 0 along y); the jump back across the x
  // edge is a (nx - 1) on each of ny lines, none across the y edge.
  for (const auto& [nx, ny] : {std::pair{8, 5}, std::pair{5, 12}}) {
    const double a = 3e-7;
    Field z(nx, ny);
    for (Eigen::Index j = 0; j < ny; ++j)
      for (Eigen::Index i = 0; i < nx; ++i) z(i, j) = a * static_cast<double>(i);
    const EdgeMismatch m = edge_mismatch(z);
    const double steps = (nx - 1.0) * ny, pairs = (nx - 1.0) * ny + nx * (ny - 1.0);
    CHECK(m.rms_step == Approx(a * std::sqrt(steps / pairs)).epsilon(1e-13));
    CHECK(m.rms_jump == Approx(a * (nx - 1) * std::sqrt(ny / double(nx + ny))).epsilon(1e-13));
  }
  // A map periodic in both directions (a sampled cosine) joins its copies: the jump is a step.
  Field c(16, 16);
  for (Eigen::Index j = 0; j < 16; ++j)
    for (Eigen::Index i = 0; i < 16; ++i) c(i, j) = std::cos(2 * M_PI * (i + 0.5) / 16.0);
  const EdgeMismatch m = edge_mismatch(c);
  // Across the edge: cos(2 pi 0.5/16) - cos(2 pi 15.5/16) = 0 on every x line.
  CHECK(m.rms_jump < 1e-14);
}

TEST_CASE("roughness: heights near the largest double give finite parameters",
          "[topography][roughness]") {
  // The sine and ramp above times 1e200: every parameter times 1e200 (their squares overflow
  // unscaled), and heights of +-1.7e308 alternating along x: rms height 1.7e308, mean 0.
  const double s = 1e200, A = 2e-6 * s, L = 1e-3;
  const int n = 16, m = 1;
  const double d = L / n;
  const Grid g(n, 6, L, 6 * d);
  Field z(n, 6);
  for (Eigen::Index j = 0; j < 6; ++j)
    for (Eigen::Index i = 0; i < n; ++i) z(i, j) = A * std::sin(2 * M_PI * m * g.x(i) / L);
  CHECK(rms_height(z) == Approx(A / std::sqrt(2.0)).epsilon(1e-13));
  CHECK(rms_slope(g, z, true) ==
        Approx(std::sqrt(2.0) * A * std::sin(M_PI * m / n) / d).epsilon(1e-13));
  Field ramp(8, 5);
  for (Eigen::Index j = 0; j < 5; ++j)
    for (Eigen::Index i = 0; i < 8; ++i) ramp(i, j) = 3e-7 * s * static_cast<double>(i);
  const EdgeMismatch e = edge_mismatch(ramp);
  CHECK(e.rms_step == Approx(3e-7 * s * std::sqrt(35.0 / 67.0)).epsilon(1e-13));
  CHECK(e.rms_jump == Approx(3e-7 * s * 7 * std::sqrt(5.0 / 13.0)).epsilon(1e-13));
  Field extreme(4, 2);
  extreme << 1.7e308, -1.7e308, 1.7e308, -1.7e308, -1.7e308, 1.7e308, -1.7e308, 1.7e308;
  CHECK(rms_height(extreme) == Approx(1.7e308).epsilon(1e-15));
}

TEST_CASE("a file's map that no grid holds is refused naming the file and what is wrong",
          "[topography]") {
  topography::Topography t;
  t.heights = Field::Zero(70, 2);
  t.lx = 70 * 1e-321;  // a spacing of 1e-321 m: a map of 7e-320 m
  t.ly = 1.0;
  CHECK_THROWS_WITH(topography::topography_grid("h.x3p", t),
                    Catch::Contains("h.x3p: the spacing 1e-321") &&
                        Catch::Contains(" m along x makes the map 6.9") &&
                        Catch::Contains("outside the [1e-100, 1e+100] m a grid takes"));
  t.lx = 1.0;
  t.ly = std::numeric_limits<double>::infinity();  // 2 points of 1e308 m
  CHECK_THROWS_WITH(topography::topography_grid("h.nc", t),
                    Catch::Contains("h.nc: the spacing inf m along y makes the map inf m long"));
  t.heights = Field::Zero(70000, 2);
  t.lx = t.ly = std::nullopt;
  CHECK_THROWS_WITH(topography::topography_grid("h.csv", t),
                    Catch::Contains("h.csv: 70000 points along x, more than the 65536"));
}
