// The partial-slip reference (validation/cattaneo_mindlin.hpp) against what it must satisfy
// independently of its own formulas: the traction's integral is the tangential load (Johnson 1985,
// eq. 7.40 integrated by quadrature), Mindlin's initial tangential stiffness 8 G a/(2 - nu)
// (Johnson eq. 7.45), and the loop energy of eq. 7.59 equal to the area between the unloading and
// reloading curves of Masing's rule, integrated numerically.
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "tests/test_materials.hpp"
#include "validation/cattaneo_mindlin.hpp"

using namespace coatfft;

namespace {

// A steel ball of 10 mm radius pressed with 100 N on steel, mu = 0.3.
CattaneoMindlin steel_ball() {
  return cattaneo_mindlin(100.0, 10e-3, steel, 0.3);
}

}  // namespace

TEST_CASE("Cattaneo-Mindlin: the traction sums to the tangential load, and never exceeds mu p",
          "[cattaneo_mindlin]") {
  const CattaneoMindlin cm = steel_ball();
  const double a = cm.hertz.contact_radius, mu_p = cm.friction * cm.hertz.load;
  boost::math::quadrature::tanh_sinh<double> quadrature;
  for (const double x : {0.0, 0.1, 0.5, 0.9, 0.999}) {
    const double q_load = x * mu_p, c = cm.stick_radius(q_load);
    CHECK(c == Approx(a * std::cbrt(1.0 - x)).epsilon(1e-15));
    // In two pieces: the traction's slope jumps at the stick zone's edge.
    const auto ring = [&](double r) { return 2.0 * std::numbers::pi * r * cm.traction(r, q_load); };
    const double total =
        (c > 0.0 ? quadrature.integrate(ring, 0.0, c) : 0.0) + quadrature.integrate(ring, c, a);
    INFO("Q/(mu P) = " << x);
    CHECK(total == Approx(q_load).epsilon(1e-10).margin(1e-12 * mu_p));
    for (const double r : {0.0, 0.5 * c, 0.999 * c, c, 0.5 * (a + c), a, 1.5 * a}) {
      const double limit = cm.friction * cm.hertz.pressure(r);
      CHECK(cm.traction(r, q_load) <= limit * (1.0 + 1e-15));
      if (r >= c) CHECK(cm.traction(r, q_load) == limit);  // the slip zone slips
    }
  }
}

TEST_CASE("Cattaneo-Mindlin: the shift starts with Mindlin's stiffness and ends at full sliding",
          "[cattaneo_mindlin]") {
  const CattaneoMindlin cm = steel_ball();
  const double a = cm.hertz.contact_radius, mu_p = cm.friction * cm.hertz.load;
  const double g = steel.shear_modulus(), nu = steel.poisson_ratio();
  // Johnson eq. 7.45: dQ/d delta = 8 G a/(2 - nu) at Q = 0; the shift's curvature makes the
  // secant at Q = 1e-6 mu P differ from it by about 1e-7.
  const double q_small = 1e-6 * mu_p;
  CHECK(q_small / cm.shift(q_small) == Approx(8.0 * g * a / (2.0 - nu)).epsilon(1e-6));
  CHECK(cm.shift(0.0) == 0.0);
  // Towards full sliding: 3 mu P (2 - nu)/(16 G a).
  CHECK(cm.shift(std::nextafter(mu_p, 0.0)) ==
        Approx(3.0 * mu_p * (2.0 - nu) / (16.0 * g * a)).epsilon(1e-9));
  // Masing's rule: the unloading curve starts at the reversal point and ends at its mirror.
  const double q_star = 0.6 * mu_p;
  CHECK(cm.unloading_shift(q_star, q_star) == cm.shift(q_star));
  CHECK(cm.unloading_shift(q_star, -q_star) == Approx(-cm.shift(q_star)).epsilon(1e-14));
}

TEST_CASE("Mindlin-Deresiewicz: the loop energy is the area of Masing's loop",
          "[cattaneo_mindlin]") {
  const CattaneoMindlin cm = steel_ball();
  const double a = cm.hertz.contact_radius, mu_p = cm.friction * cm.hertz.load;
  boost::math::quadrature::tanh_sinh<double> quadrature;
  for (const double x : {0.05, 0.3, 0.7, 0.95}) {
    const double q_star = x * mu_p;
    // The loop between -Q* and Q*: unloading above, reloading (its mirror) below.
    const auto width = [&](double q) {
      return cm.unloading_shift(q_star, q) + cm.unloading_shift(q_star, -q);
    };
    INFO("Q*/(mu P) = " << x);
    CHECK(quadrature.integrate(width, -q_star, q_star) ==
          Approx(cm.loop_energy(q_star)).epsilon(1e-9));
  }
  // Small amplitudes: W -> mu^2 P^2 (2 - nu) x^3/(36 G a) (docs/theory.md 6.5), to O(x).
  const double x = 1e-3;
  CHECK(cm.loop_energy(x * mu_p) / (mu_p * mu_p * cm.compliance * x * x * x / (36.0 * a)) ==
        Approx(1.0).epsilon(2e-3));
}

TEST_CASE("Cattaneo-Mindlin refuses loads out of range", "[cattaneo_mindlin]") {
  const CattaneoMindlin cm = steel_ball();
  const double mu_p = cm.friction * cm.hertz.load;
  CHECK_THROWS_AS(cm.shift(mu_p), InvalidArgument);
  CHECK_THROWS_AS(cm.stick_radius(-1.0), InvalidArgument);
  CHECK_THROWS_AS(cm.loop_energy(NAN), InvalidArgument);
  CHECK_THROWS_AS(cm.unloading_shift(0.5 * mu_p, 0.6 * mu_p), InvalidArgument);
  CHECK_THROWS_AS(cattaneo_mindlin(100.0, 10e-3, steel, 0.0), InvalidArgument);
}

TEST_CASE("rms_traction_error: zero on the reference's own traction, the offset of a shifted one",
          "[cattaneo_mindlin]") {
  const CattaneoMindlin cm = steel_ball();
  const double a = cm.hertz.contact_radius, q = 0.5 * cm.friction * cm.hertz.load;
  const Grid g(33, 33, 4.125 * a, 4.125 * a);
  Field qx(g.nx(), g.ny());
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      qx(i, j) = cm.traction(std::hypot(g.x(i), g.y(j)), q);
  CHECK(rms_traction_error(g, qx, cm, q) == 0.0);
  // A constant offset inside the contact is its own rms; cells outside are not counted.
  const double offset = 0.01 * cm.friction * cm.hertz.max_pressure;
  Field shifted = qx + offset;
  CHECK(rms_traction_error(g, shifted, cm, q) == Approx(0.01).epsilon(1e-12));
  CHECK_THROWS_AS(rms_traction_error(g, Field::Zero(3, 3), cm, q), InvalidArgument);
}
