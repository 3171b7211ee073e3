// Closed-form Hertz and uniform-disk displacements (validation/hertz) against their known values,
// and DC-FFT on the Hertz pressure against them (Spinu 2021, Fig. 2).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <numbers>

#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "core/error.hpp"
#include "materials/catalog.hpp"
#include "validation/hertz.hpp"

using coatfft::hertz_displacement;
using coatfft::uniform_disk_displacement;

namespace {
constexpr double p0 = 1e9;        // Pa
constexpr double kRadius = 1e-3;  // m
const double steel_e_star = coatfft::material_by_name("steel").plane_strain_modulus();
using std::numbers::pi;
}  // namespace

TEST_CASE("hertz_displacement matches its known values", "[hertz]") {
  // Centre and edge values of docs/theory.md 1.4; both branches are a few roundings from them.
  CHECK(hertz_displacement(0.0, p0, kRadius, steel_e_star) ==
        Approx(pi * p0 * kRadius / (2 * steel_e_star)).epsilon(1e-15));
  CHECK(hertz_displacement(kRadius, p0, kRadius, steel_e_star) ==
        Approx(pi * p0 * kRadius / (4 * steel_e_star)).epsilon(1e-15));
  // Continuity at r = a between (1.6) and (1.7), and at r = 2a between (1.7) and its series.
  for (double edge : {kRadius, 2 * kRadius}) {
    const double below = hertz_displacement(edge * (1 - 1e-12), p0, kRadius, steel_e_star);
    const double above = hertz_displacement(edge * (1 + 1e-12), p0, kRadius, steel_e_star);
    // The slope is O(u/a), so a 1e-12 step moves u by ~1e-12 relative.
    CHECK(above == Approx(below).epsilon(1e-11));
  }
  // Far field P/(pi E* r), P = 2/3 pi a^2 p0, with relative correction (a/r)^2/10 from the series
  // (2/15 t^5 next to 4/3 t^3): check both the limit and the first correction.
  const double load = 2.0 / 3.0 * pi * kRadius * kRadius * p0;
  for (double rho : {3.0, 10.0, 1e3, 1e6}) {
    const double r = rho * kRadius;
    const double u = hertz_displacement(r, p0, kRadius, steel_e_star);
    const double point = load / (pi * steel_e_star * r);
    // Next series term: (3/70) t^7 / ((4/3) t^3) = 0.032 t^4; roundoff ~1e-15.
    CHECK(std::abs(u / point - 1.0 - 0.1 / (rho * rho)) < 0.04 / std::pow(rho, 4) + 1e-15);
  }
  // (1.7) evaluated directly at r = 1.5 a (no series there) against its algebraic value.
  const double r = 1.5 * kRadius;
  const double direct = p0 / (2 * kRadius * steel_e_star) *
                        ((2 * kRadius * kRadius - r * r) * std::asin(kRadius / r) +
                         kRadius * std::sqrt(r * r - kRadius * kRadius));
  CHECK(hertz_displacement(r, p0, kRadius, steel_e_star) == Approx(direct).epsilon(1e-15));
  // Series branch against (1.7) in long double at r = 3a, where (1.7) in double would lose a digit.
  const long double rl = 3.0L * kRadius;
  const long double al = kRadius;
  const long double exact =
      (long double)p0 / (2 * al * steel_e_star) *
      ((2 * al * al - rl * rl) * std::asin(al / rl) + al * std::sqrt(rl * rl - al * al));
  CHECK(hertz_displacement(3 * kRadius, p0, kRadius, steel_e_star) ==
        Approx(double(exact)).epsilon(1e-14));
  CHECK_THROWS_AS(hertz_displacement(-1.0, p0, kRadius, steel_e_star), coatfft::InvalidArgument);
  CHECK_THROWS_AS(hertz_displacement(0.0, p0, 0.0, steel_e_star), coatfft::InvalidArgument);
}

TEST_CASE("uniform_disk_displacement matches its known values", "[hertz]") {
  const double p = 2e8;
  CHECK(uniform_disk_displacement(0.0, p, kRadius, steel_e_star) ==
        Approx(2 * p * kRadius / steel_e_star).epsilon(1e-15));
  CHECK(uniform_disk_displacement(kRadius, p, kRadius, steel_e_star) ==
        Approx(4 * p * kRadius / (pi * steel_e_star)).epsilon(1e-15));
  // Continuity across r = a: the outside form's (1 - k^2) K(k) -> 0 only logarithmically slowly,
  // u is continuous with an infinite slope ~ log, so a 1e-12 step moves it by ~1e-11.
  CHECK(uniform_disk_displacement(kRadius * (1 + 1e-12), p, kRadius, steel_e_star) ==
        Approx(uniform_disk_displacement(kRadius * (1 - 1e-12), p, kRadius, steel_e_star))
            .epsilon(1e-10));
  // Far field P/(pi E* r) with P = pi a^2 p; first correction (a/r)^2/8 (E, K series).
  for (double rho : {5.0, 100.0, 1e5}) {
    const double r = rho * kRadius;
    const double point = p * kRadius * kRadius / (steel_e_star * r);
    const double u = uniform_disk_displacement(r, p, kRadius, steel_e_star);
    // Next term of the series is O(k^4) with a coefficient below 0.1; roundoff ~1e-15.
    CHECK(std::abs(u / point - 1.0 - 0.125 / (rho * rho)) < 0.1 / std::pow(rho, 4) + 1e-15);
  }
}

namespace {
// Independent reference (docs/theory.md 1.6 (B)): superpose rings. A unit line load on the ring of
// radius s displaces the surface at radius r by s * 2 pi / AGM(r + s, |r - s|) / (pi E*) (the ring
// kernel 4 K(m) s / (r + s) in AGM form), so u(r) = (1/(pi E*)) int_0^a p(s) s 2 pi / AGM ds,
// integrated by GSL QAGS with the logarithmic singularity at s = r as an interval end.
double agm(double x, double y) {
  for (int it = 0; it < 100 && std::abs(x - y) > 1e-16 * x; ++it) {
    const double m = 0.5 * (x + y);
    y = std::sqrt(x * y);
    x = m;
  }
  return 0.5 * (x + y);
}

double ring_superposition(double r, const std::function<double(double)>& pressure) {
  std::function<double(double)> f = [&](double s) {
    return pressure(s) * s * 2.0 * pi / agm(r + s, std::abs(r - s));
  };
  gsl_function g{
      [](double s, void* fp) { return (*static_cast<std::function<double(double)>*>(fp))(s); }, &f};
  gsl_set_error_handler_off();
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(1000);
  double total = 0.0;
  const double split = std::min(r, kRadius);
  for (auto [lo, hi] : {std::pair{0.0, split}, {split, kRadius}}) {
    if (hi <= lo) continue;
    double result = 0.0;
    double err = 0.0;
    REQUIRE(gsl_integration_qags(&g, lo, hi, 0.0, 1e-13, 1000, ws, &result, &err) == GSL_SUCCESS);
    total += result;
  }
  gsl_integration_workspace_free(ws);
  return total / (pi * steel_e_star);
}
}  // namespace

TEST_CASE("Hertz and uniform-disk closed forms equal a superposition of ring loads", "[hertz]") {
  const double p = 3e8;
  for (double rho : {0.1, 0.3, 0.5, 0.9, 0.999, 1.001, 1.1, 1.5, 2.0, 2.5, 5.0, 20.0}) {
    const double r = rho * kRadius;
    INFO("r / a = " << rho);
    // QAGS at epsrel 1e-13 with the log singularity at an interval end; measured agreement
    // <= 1e-14 at all these radii, so 1e-12 leaves margin yet sees any slip in (1.6), (1.7),
    // the series beyond 2a or (1.9).
    const double hertz_rings = ring_superposition(
        r, [](double s) { return p0 * std::sqrt(1 - s * s / (kRadius * kRadius)); });
    const double disk_rings = ring_superposition(r, [p](double) { return p; });
    CHECK(hertz_displacement(r, p0, kRadius, steel_e_star) == Approx(hertz_rings).epsilon(1e-12));
    CHECK(uniform_disk_displacement(r, p, kRadius, steel_e_star) ==
          Approx(disk_rings).epsilon(1e-12));
  }
}

TEST_CASE("centre_relative_error normalises by the centre displacement", "[hertz]") {
  CHECK(coatfft::centre_relative_error(1.1, 1.0, 2.0) == Approx(0.05));
  CHECK_THROWS_AS(coatfft::centre_relative_error(1.0, 1.0, 0.0), coatfft::InvalidArgument);
}
