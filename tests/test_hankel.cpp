// The Hankel-integral displacement reference against the homogeneous closed forms (docs/theory.md
// (1.6), (1.7), (1.9), via validation/hertz.hpp), against itself by two independent routes for
// coated and layered bodies, and against the thin- and thick-coating limits.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "frf/coated_frf.hpp"
#include "frf/half_space_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"
#include "validation/hankel_displacement.hpp"
#include "validation/hertz.hpp"

using coatfft::AxisymmetricLoad;
using coatfft::CoatedFrf;
using coatfft::HalfSpaceFrf;
using coatfft::HankelRoute;
using coatfft::Interface;
using coatfft::Material;

namespace {

constexpr double kRhos[] = {0.0, 0.3, 0.5, 0.9, 1.0, 1.1, 2.0, 5.0};

double closed_form(AxisymmetricLoad load, double r, double amplitude, double a, double e_star) {
  return load == AxisymmetricLoad::hertz
             ? coatfft::hertz_displacement(r, amplitude, a, e_star)
             : coatfft::uniform_disk_displacement(r, amplitude, a, e_star);
}

double rel_err(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

}  // namespace

TEST_CASE("Load transforms are 2 pi times the Hankel transform of the pressure", "[hankel]") {
  const double a = 2e-3;
  // k -> 0: P^(0) = total load: (2/3) pi p0 a^2 (Hertz), pi p a^2 (uniform).
  CHECK(coatfft::axisymmetric_load_transform(AxisymmetricLoad::hertz, 3.0, a, 0.0) ==
        Approx(2.0 / 3.0 * std::numbers::pi * 3.0 * a * a).epsilon(1e-15));
  CHECK(coatfft::axisymmetric_load_transform(AxisymmetricLoad::uniform_disk, 3.0, a, 0.0) ==
        Approx(std::numbers::pi * 3.0 * a * a).epsilon(1e-15));
  // At ka = 2: j1(2)/2 = (sin 2 - 2 cos 2)/8 and J1(2)/2 = 0.5767248077568734/2 (A&S Table 9.1).
  const double s = 2.0;
  CHECK(coatfft::axisymmetric_load_transform(AxisymmetricLoad::hertz, 1.0, a, s / a) ==
        Approx(2 * std::numbers::pi * a * a * (std::sin(s) - s * std::cos(s)) / (s * s * s))
            .epsilon(1e-14));
  CHECK(coatfft::axisymmetric_load_transform(AxisymmetricLoad::uniform_disk, 1.0, a, s / a) ==
        Approx(2 * std::numbers::pi * a * a * 0.5767248077568734 / s).epsilon(1e-14));
}

TEST_CASE("Direct Hankel route reproduces the homogeneous closed forms", "[hankel]") {
  const Material m(2.1e11, 0.3);
  const HalfSpaceFrf frf(m);
  const double a = 1e-4, p = 1e9;
  double worst = 0.0;
  for (auto load : {AxisymmetricLoad::hertz, AxisymmetricLoad::uniform_disk}) {
    for (double rho : kRhos) {
      const double ref = closed_form(load, rho * a, p, a, m.plane_strain_modulus());
      const double direct =
          coatfft::hankel_displacement(frf, load, p, a, rho * a, 1e-10, HankelRoute::direct);
      const double split = coatfft::hankel_displacement(frf, load, p, a, rho * a);
      INFO("load " << static_cast<int>(load) << ", r/a = " << rho << ": direct "
                   << rel_err(direct, ref));
      worst = std::max(worst, rel_err(direct, ref));
      // The direct route never uses the closed forms: quadrature to rel_tol 1e-10 plus an
      // asymptotic tail exact to ~1e-16; 1e-9 allows for the accumulated panel errors.
      CHECK(rel_err(direct, ref) < 1e-9);
      // Split: the remainder H - c_inf/k is identically zero here.
      CHECK(rel_err(split, ref) < 1e-14);
    }
  }
  WARN("direct Hankel route vs closed forms, worst relative error: " << worst);
}

TEST_CASE("Coated and layered bodies: split and direct routes agree", "[hankel]") {
  const Material tin(4e11, 0.25), steel(2.1e11, 0.3), polymer(3e9, 0.4);
  const double a = 1e-4, p = 1e9;
  const CoatedFrf hard(tin, 0.3 * a, steel, Interface::bonded);
  const CoatedFrf soft(polymer, 0.5 * a, steel, Interface::frictionless);
  const coatfft::MultilayerFrf layered(coatfft::LayerStack(
      {{tin, 0.2 * a, Interface::bonded}, {polymer, 0.3 * a, Interface::frictionless}}, steel));
  const coatfft::Frf* frfs[] = {&hard, &soft, &layered};
  double worst = 0.0;
  for (const coatfft::Frf* frf : frfs) {
    for (auto load : {AxisymmetricLoad::hertz, AxisymmetricLoad::uniform_disk}) {
      // The layered FRF is ~3x dearer per call (and far more under a Debug/ASan build): fewer
      // radii, still covering the oscillatory (r = 0) and non-oscillatory (r = a) tails.
      const std::vector<double> rhos =
          frf == &layered ? std::vector<double>{0.0, 1.0} : std::vector<double>{0.0, 0.5, 1.0, 2.0};
      for (double rho : rhos) {
        const double split = coatfft::hankel_displacement(*frf, load, p, a, rho * a);
        const double direct =
            coatfft::hankel_displacement(*frf, load, p, a, rho * a, 1e-10, HankelRoute::direct);
        INFO(frf->name() << ", load " << static_cast<int>(load) << ", r/a = " << rho);
        // Two quadratures sharing only the FRF, each aiming at 1e-10.
        CHECK(rel_err(split, direct) < 1e-8);
        worst = std::max(worst, rel_err(split, direct));
        // The coated value lies between the two homogeneous bounds (coating alone, substrate
        // alone).
        const double u_top = closed_form(load, rho * a, p, a, 2.0 / frf->c_inf());
        const double u_sub = closed_form(load, rho * a, p, a, 2.0 / frf->c0());
        if (frf == &hard) CHECK((split < u_sub && split > u_top));
      }
    }
  }
  WARN("split vs direct Hankel routes (coated/layered), worst relative difference: " << worst);
}

TEST_CASE("Coated Hertz displacement tends to the substrate (h/a -> 0) and coating (h/a -> inf)",
          "[hankel]") {
  const Material coating(4e11, 0.25), substrate(7e10, 0.33);
  const double a = 1e-4, p = 1e9;
  const double R = coating.plane_strain_modulus() / substrate.plane_strain_modulus();
  for (auto interface : {Interface::bonded, Interface::frictionless}) {
    double previous_thin = 1.0, previous_thick = 1.0;
    for (double ratio : {1e-2, 1e-3}) {
      const CoatedFrf thin(coating, ratio * a, substrate, interface);
      const CoatedFrf thick(coating, a / ratio, substrate, interface);
      for (double rho : {0.0, 1.0}) {
        const double u_thin =
            coatfft::hankel_displacement(thin, AxisymmetricLoad::hertz, p, a, rho * a);
        const double u_thick =
            coatfft::hankel_displacement(thick, AxisymmetricLoad::hertz, p, a, rho * a);
        const double e_thin = rel_err(
            u_thin, coatfft::hertz_displacement(rho * a, p, a, substrate.plane_strain_modulus()));
        const double e_thick = rel_err(
            u_thick, coatfft::hertz_displacement(rho * a, p, a, coating.plane_strain_modulus()));
        INFO("h/a = " << ratio << " and " << 1 / ratio << ", r/a = " << rho << ": " << e_thin
                      << ", " << e_thick);
        // The deviations are first order in h/a (thin) and a/h (thick), with the modulus contrast
        // as coefficient (e.g. thick: the load seen at depth h ~ P/(pi h) (1/E2* - 1/E1*) over
        // u ~ p a/E1*): bound them by 2 |contrast - 1| ratio, and require them to shrink >= 5x
        // per decade of the ratio (measured: ~10x).
        CHECK(e_thin < 2.0 * std::abs(1.0 / R - 1.0) * ratio);
        CHECK(e_thick < 2.0 * std::abs(R - 1.0) * ratio);
        if (rho == 0.0 && ratio == 1e-3) {
          CHECK(e_thin < 0.2 * previous_thin);
          CHECK(e_thick < 0.2 * previous_thick);
        }
        if (rho == 0.0) {
          previous_thin = e_thin;
          previous_thick = e_thick;
        }
      }
    }
  }
}

TEST_CASE("hankel_displacement refuses bad arguments", "[hankel][bad_input]") {
  const HalfSpaceFrf frf(Material(1e9, 0.3));
  CHECK_THROWS_AS(coatfft::hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, 0.0, 0.0),
                  coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, 1.0, -1.0),
                  coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, 1.0, 0.0, 0.1),
                  coatfft::InvalidArgument);
}

TEST_CASE("hankel_displacement far away: the substrate's half-space, never NaN",
          "[hankel][far_field]") {
  const Material tin(4e11, 0.25), steel(2.1e11, 0.3), polymer(3e9, 0.4);
  const double a = 1e-4, p = 1e9;
  const HalfSpaceFrf half_space(steel);
  const CoatedFrf hard(tin, 0.3 * a, steel, Interface::bonded);
  const CoatedFrf soft(polymer, 0.5 * a, steel, Interface::frictionless);
  // Beyond the quadrature's reach: the half-space of compliance c0 under the load of force
  // F = 2 pi p a^2 Phi(0), u = F c0 / (2 pi r) to (a/r)^2. It read NaN at r = 1e300 m (r^2
  // overflowed in the Hertz closed form); there u is subnormal, with 13 digits left.
  for (const double r : {1e7, 1e100, 1e300}) {
    for (const coatfft::Frf* frf : std::vector<const coatfft::Frf*>{&half_space, &hard, &soft}) {
      for (auto load : {AxisymmetricLoad::hertz, AxisymmetricLoad::uniform_disk}) {
        INFO(frf->name() << ", load " << static_cast<int>(load) << ", r = " << r);
        const double phi0 = load == AxisymmetricLoad::hertz ? 1.0 / 3.0 : 0.5;
        const double u = coatfft::hankel_displacement(*frf, load, p, a, r);
        REQUIRE(std::isfinite(u));
        CHECK(u == Approx(p * a * a * phi0 * frf->c0() / r).epsilon(r == 1e300 ? 1e-12 : 1e-14));
      }
    }
  }
  const double e_star = steel.plane_strain_modulus();
  CHECK(coatfft::hertz_displacement(1e300, p, 1.0, e_star) ==
        Approx(2.0 * p / (3.0 * e_star) / 1e300).epsilon(1e-14));
  CHECK(coatfft::uniform_disk_displacement(1e300, p, 1.0, e_star) ==
        Approx(p / e_star / 1e300).epsilon(1e-14));
  // Where the panels reach, the quadrature approaches that half-space like r^-2: the k^2 term of
  // k H (its odd terms give nothing outside the load), the law the far field's bound rests on.
  const auto from_far_field = [&](double r) {
    const double u = coatfft::hankel_displacement(hard, AxisymmetricLoad::hertz, p, a, r);
    return u / coatfft::hertz_displacement(r, p, a, 2.0 / hard.c0()) - 1.0;
  };
  const double near = from_far_field(1e-2), far = from_far_field(3e-2);
  CHECK(near / far == Approx(9.0).epsilon(1e-2));
  // Between the two (beyond the panels, the far field not yet within rel_tol): refused by r.
  CHECK_THROWS_WITH(coatfft::hankel_displacement(hard, AxisymmetricLoad::hertz, p, a, 10.0, 1e-12),
                    Catch::Contains("r = 10 m") && Catch::Contains("far field"));
}
