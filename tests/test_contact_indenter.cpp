// Indenter shapes (contact/indenter.hpp) and the closed-form contact references
// (validation/hertz_contact.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact/indenter.hpp"
#include "core/error.hpp"
#include "materials/material.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

// Independent reference for the sphere: the textbook form R - sqrt(R^2 - r^2) in long double
// (64-bit mantissa), against which the library's cancellation-free double form is checked.
double sphere_reference(double x, double y, double R) {
  const long double r2 = static_cast<long double>(x) * x + static_cast<long double>(y) * y;
  const long double Rl = R;
  return static_cast<double>(Rl - std::sqrt(Rl * Rl - r2));
}

}  // namespace

TEST_CASE("Sphere height is R - sqrt(R^2 - r^2) at every cell centre", "[contact][indenter]") {
  const Grid grid(7, 5, 2.0e-3, 1.0e-3);
  const double R = 5.0e-3;
  const Field h = height(grid, Sphere{R});
  REQUIRE(h.rows() == 7);
  REQUIRE(h.cols() == 5);
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double ref = sphere_reference(grid.x(i), grid.y(j), R);
      // The long-double form loses ~R^2/r^2 * 1e-19 relative; 1e-13 leaves room for it at the
      // smallest r here (r = 0 gives 0 exactly in both forms).
      CHECK(h(i, j) == Approx(ref).epsilon(1e-13).margin(1e-25));
    }
  }
  CHECK(h(3, 2) == 0.0);  // odd grid: the centre cell sits on the apex
}

TEST_CASE("Sphere and paraboloid agree to O(r^4 / R^3)", "[contact][indenter]") {
  const Grid grid(16, 16, 1.0e-3, 1.0e-3);
  const double R = 0.02;
  const Field s = height(grid, Sphere{R});
  const Field p = height(grid, Paraboloid{R});
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double r2 = grid.x(i) * grid.x(i) + grid.y(j) * grid.y(j);
      CHECK(p(i, j) == Approx(r2 / (2 * R)).epsilon(1e-15));
      // Series: R - sqrt(R^2 - r^2) = r^2/(2R) + r^4/(8R^3) + r^6/(16 R^5) + 5 r^8/(128 R^7) + ...;
      // here r^2/R^2 <= 1.3e-3, so the first omitted term is <= 5e-7 of the difference, and the
      // difference itself is formed to ~1e-16 * 2R^2/r^2 <= 1e-12: 1e-6 relative.
      const double r4 = r2 * r2;
      CHECK(s(i, j) - p(i, j) == Approx(r4 / (8 * R * R * R) + r4 * r2 / (16 * std::pow(R, 5)))
                                     .epsilon(1e-6)
                                     .margin(1e-30));
    }
  }
}

TEST_CASE("Cylinder: parabolic cross-section, flat part, rounded ends", "[contact][indenter]") {
  const Grid grid(40, 9, 4.0e-3, 1.0e-3);  // dx = 1e-4, dy = 1.111e-4
  const double R = 0.01;
  const double L = 2.0e-3;
  const double Re = 5.0e-3;
  const Field h = height(grid, Cylinder{R, L, Re});
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double x = grid.x(i);
      const double y = grid.y(j);
      const double ax = std::abs(x);
      const double expected =
          y * y / (2 * R) + (ax > L / 2 ? (ax - L / 2) * (ax - L / 2) / (2 * Re) : 0.0);
      CHECK(h(i, j) == Approx(expected).epsilon(1e-14).margin(1e-30));
    }
  }
  // Along the straight part the height does not depend on x.
  CHECK(h(10, 2) == h(29, 2));
  CHECK(h(20, 4) == 0.0);
  // L = 0 with Re = R is the paraboloid.
  const Field c0 = height(grid, Cylinder{R, 0.0, R});
  const Field p0 = height(grid, Paraboloid{R});
  CHECK((c0 - p0).abs().maxCoeff() <= 1e-15 * p0.maxCoeff());
}

TEST_CASE("Flat punch: zero on the face, (r - a)^2/(2 rho) beyond", "[contact][indenter]") {
  const Grid grid(32, 32, 4.0e-3, 4.0e-3);
  const double a = 1.0e-3;
  const double rho = 1.0e-4;
  const Field h = height(grid, FlatPunch{a, rho});
  std::ptrdiff_t n_face = 0;
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double r = std::hypot(grid.x(i), grid.y(j));
      if (r <= a) {
        CHECK(h(i, j) == 0.0);
        ++n_face;
      } else {
        CHECK(h(i, j) == Approx((r - a) * (r - a) / (2 * rho)).epsilon(1e-13));
      }
    }
  }
  // a / dx = 8: the face covers pi 8^2 = 201.1 cells, up to the pixelation of the circle, which is
  // bounded by the cells the circle crosses (about its perimeter, 2 pi 8 = 50, each half in).
  CHECK(std::abs(static_cast<double>(n_face) - std::numbers::pi * 64.0) < 25.0);
}

TEST_CASE("Height map is passed through; the Indenter variant dispatches", "[contact][indenter]") {
  const Grid grid(3, 2, 1.0, 1.0);
  Field m(3, 2);
  m << 1, 2, 3, 4, 5, 6;
  CHECK((height(grid, HeightMap{m}) == m).all());
  const Indenter ind = Paraboloid{2.0};
  CHECK((height(grid, ind) == height(grid, Paraboloid{2.0})).all());
  const Indenter map = HeightMap{m};
  CHECK((height(grid, map) == m).all());
}

TEST_CASE("A slab's rows of any indenter are those rows of its whole height field",
          "[contact][indenter]") {
  // Rows sampled alone (a distributed solve's slab) against the whole field's, bit for bit.
  const Grid grid(9, 7, 2.0e-3, 1.5e-3);
  Field m = Field::Random(9, 7);
  for (const Indenter& ind :
       {Indenter{Sphere{5e-3}}, Indenter{Paraboloid{4e-3}}, Indenter{Cylinder{3e-3, 0.5e-3, 1e-3}},
        Indenter{FlatPunch{0.4e-3, 1e-3}}, Indenter{HeightMap{m}}}) {
    const Field whole = height(grid, ind);
    for (auto [y0, rows] : {std::pair{0, 7}, {2, 3}, {6, 1}, {7, 0}})
      CHECK((height_rows(grid, ind, y0, rows) == whole.middleCols(y0, rows)).all());
  }
  CHECK_THROWS_WITH(height_rows(grid, Paraboloid{4e-3}, 5, 3), Catch::Contains("ny = 7"));
  CHECK_THROWS_AS(height_rows(grid, Paraboloid{4e-3}, -1, 2), InvalidArgument);
  CHECK_THROWS_AS(height_rows(grid, Sphere{1e-4}, 0, 1), InvalidArgument);  // checked as height()
}

TEST_CASE("Indenters refuse bad input with a message naming the value",
          "[contact][indenter][bad_input]") {
  const Grid grid(8, 8, 2.0e-3, 2.0e-3);  // farthest centre at r = 0.875e-3 * sqrt(2) = 1.237e-3
  CHECK_THROWS_WITH(height(grid, Sphere{1.2e-3}), Catch::Contains("farthest cell centre"));
  CHECK_THROWS_AS(height(grid, Sphere{1.2e-3}), InvalidArgument);
  CHECK_NOTHROW(height(grid, Sphere{1.3e-3}));
  CHECK_THROWS_AS(height(grid, Sphere{-1.0}), InvalidArgument);
  CHECK_THROWS_AS(height(grid, Paraboloid{0.0}), InvalidArgument);
  CHECK_THROWS_AS(height(grid, Paraboloid{std::numeric_limits<double>::infinity()}),
                  InvalidArgument);
  CHECK_THROWS_AS(height(grid, Cylinder{1.0, -1.0, 1.0}), InvalidArgument);
  CHECK_THROWS_AS(height(grid, Cylinder{1.0, 1.0, 0.0}), InvalidArgument);
  CHECK_THROWS_AS(height(grid, FlatPunch{1e-3, 0.0}), InvalidArgument);
  CHECK_THROWS_AS(height(grid, FlatPunch{std::nan(""), 1e-3}), InvalidArgument);
  CHECK_THROWS_WITH(height(grid, HeightMap{Field::Zero(8, 7)}), Catch::Contains("(8, 7)"));
  Field bad = Field::Zero(8, 8);
  bad(2, 5) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(height(grid, HeightMap{bad}), Catch::Contains("h(2, 5)"));
}

TEST_CASE("Hertz sphere closed forms", "[contact][hertz]") {
  // Reference numbers computed by hand: W = 10 N, R = 10 mm, E* = 100 GPa gives
  // a^3 = 3 * 10 * 0.01 / 4e11 = 7.5e-13 m^3.
  const HertzSphere hs = hertz_sphere_for_load(10.0, 0.01, 1e11);
  const double a = std::cbrt(7.5e-13);
  CHECK(hs.contact_radius == Approx(a).epsilon(1e-15));
  CHECK(hs.max_pressure == Approx(15.0 / (std::numbers::pi * a * a)).epsilon(1e-15));
  CHECK(hs.approach == Approx(a * a / 0.01).epsilon(1e-15));
  // The load is the integral of p0 sqrt(1 - r^2/a^2): W = (2/3) pi a^2 p0.
  CHECK(2.0 / 3.0 * std::numbers::pi * a * a * hs.max_pressure == Approx(10.0).epsilon(1e-14));
  CHECK(hs.pressure(0.0) == hs.max_pressure);
  CHECK(hs.pressure(0.6 * a) == Approx(0.8 * hs.max_pressure).epsilon(1e-14));
  CHECK(hs.pressure(1.5 * a) == 0.0);
  // Approach form inverts the load form.
  const HertzSphere back = hertz_sphere_for_approach(hs.approach, 0.01, 1e11);
  CHECK(back.load == Approx(10.0).epsilon(1e-14));
  CHECK(back.contact_radius == Approx(a).epsilon(1e-14));
  CHECK_THROWS_AS(hertz_sphere_for_load(0.0, 0.01, 1e11), InvalidArgument);
  CHECK_THROWS_AS(hertz_sphere_for_approach(1e-6, -0.01, 1e11), InvalidArgument);
}

TEST_CASE("Composite modulus and flat punch closed forms", "[contact][hertz]") {
  const Material steel(210e9, 0.3);
  // Two identical bodies: E* = E / (2 (1 - nu^2)).
  CHECK(composite_modulus(steel, steel) == Approx(210e9 / (2 * 0.91)).epsilon(1e-15));
  const Material glass(70e9, 0.22);
  const double inv = 0.91 / 210e9 + (1 - 0.22 * 0.22) / 70e9;
  CHECK(composite_modulus(steel, glass) == Approx(1.0 / inv).epsilon(1e-15));
  CHECK(flat_punch_load(1e-3, 2e-6, 1e11) == Approx(2 * 1e-3 * 1e11 * 2e-6).epsilon(1e-15));
  // The punch pressure integrates to W: 2 pi int_0^a W r / (2 pi a sqrt(a^2 - r^2)) dr = W.
  CHECK(flat_punch_pressure(0.0, 1e-3, 4.0) == Approx(4.0 / (2 * std::numbers::pi * 1e-6)));
  CHECK_THROWS_AS(flat_punch_pressure(1e-3, 1e-3, 4.0), InvalidArgument);
  CHECK_THROWS_AS(flat_punch_load(1e-3, 0.0, 1e11), InvalidArgument);
}

TEST_CASE("Only bodies of revolution have a contact radius", "[contact][indenter]") {
  CHECK(is_axisymmetric(Sphere{0.01}));
  CHECK(is_axisymmetric(Paraboloid{0.01}));
  CHECK(is_axisymmetric(FlatPunch{1e-3, 1e-5}));
  // A cylinder with no straight part and equal radii is the paraboloid; any other is not round.
  CHECK(is_axisymmetric(Cylinder{0.01, 0.0, 0.01}));
  CHECK_FALSE(is_axisymmetric(Cylinder{0.01, 0.0, 0.02}));
  CHECK_FALSE(is_axisymmetric(Cylinder{0.01, 1e-3, 0.01}));
  // A height map is never assumed round, even a flat one.
  CHECK_FALSE(is_axisymmetric(HeightMap{Field::Zero(4, 4)}));
}
