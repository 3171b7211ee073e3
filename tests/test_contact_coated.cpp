// Contact of a rigid paraboloid with coated bodies: the solver runs unchanged on the
// split-kernel DC-FFT operator of a coated FRF, and its results follow the physics of coatings.
#include <catch2/catch.hpp>
#include <cmath>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/dcfft_operator.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

const Material kSubstrate(210e9, 0.3);
constexpr double kRadius = 0.01;  // paraboloid tip radius R [m]
constexpr double kLoad = 50.0;    // [N]

// Bare-substrate Hertz contact radius: the length scale of every case below.
double hertz_radius() {
  return hertz_sphere_for_load(kLoad, kRadius, kSubstrate.plane_strain_modulus()).contact_radius;
}

// Domain [-3 a0, 3 a0]^2: a soft thick coating grows the contact to 10^(1/3) a0 = 2.2 a0.
Grid contact_grid() {
  return Grid(96, 96, 6 * hertz_radius(), 6 * hertz_radius());
}

ContactResult solve(SurfaceOperator& op) {
  ContactSolver solver(op);
  const ContactResult result = solver.solve_load(height(op.grid(), Paraboloid{kRadius}), kLoad);
  REQUIRE(result.converged);
  REQUIRE_FALSE(result.touches_boundary);
  return result;
}

ContactResult solve_coated(const Material& coating, double thickness,
                           Interface interface = Interface::bonded) {
  const auto frf = make_frf(LayerStack({Coating{coating, thickness, interface}}, kSubstrate));
  DcfftOperator op(split_frf_kernel(contact_grid(), *frf));
  return solve(op);
}

ContactResult solve_homogeneous(const Material& material) {
  DcfftOperator op(love_kernel(contact_grid(), material.plane_strain_modulus()));
  return solve(op);
}

double relative(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

}  // namespace

TEST_CASE("Coated contact with coating = substrate equals the homogeneous contact",
          "[contact][coated]") {
  const ContactResult bare = solve_homogeneous(kSubstrate);
  const ContactResult same = solve_coated(kSubstrate, 0.3 * hertz_radius());
  // The split kernel of an identical bonded coating equals Love's to rounding, so only the
  // solver's stopping tolerance (1e-10 relative pressure change) separates the two solutions.
  CHECK(((same.pressure - bare.pressure).abs().maxCoeff() / bare.max_pressure) < 1e-8);
  CHECK(same.contact_area == bare.contact_area);
}

TEST_CASE("A stiff coating shrinks the contact and raises the peak; a soft one the reverse",
          "[contact][coated]") {
  const ContactResult bare = solve_homogeneous(kSubstrate);
  const double h = hertz_radius();  // h/a = 1: the coating matters but does not dominate
  const ContactResult stiff = solve_coated(Material(2100e9, 0.3), h);
  const ContactResult soft = solve_coated(Material(21e9, 0.3), h);
  INFO("a: bare " << *bare.contact_radius << ", stiff " << *stiff.contact_radius << ", soft "
                  << *soft.contact_radius);
  INFO("p0: bare " << bare.max_pressure << ", stiff " << stiff.max_pressure << ", soft "
                   << soft.max_pressure);
  // The changes are large (tens of percent), far beyond the ~1% discretisation error at
  // a0/dx = 16, so the comparison cannot pass by noise.
  CHECK(*stiff.contact_radius < 0.95 * *bare.contact_radius);
  CHECK(stiff.max_pressure > 1.1 * bare.max_pressure);
  CHECK(*soft.contact_radius > 1.1 * *bare.contact_radius);
  CHECK(soft.max_pressure < 0.8 * bare.max_pressure);
}

TEST_CASE("Thick and thin coatings tend to the coating's and the substrate's contact",
          "[contact][coated]") {
  const Material coating(2100e9, 0.25);  // E ratio 10
  const double a0 = hertz_radius();
  const ContactResult as_coating = solve_homogeneous(coating);
  const ContactResult as_substrate = solve_homogeneous(kSubstrate);

  // h/a -> inf: the stress field never reaches the substrate. The distance to the coating's own
  // (numerical, same grid) solution falls as h grows: measured 8.8e-5 at h = 10 a0 and 8.8e-8 at
  // 100 a0, i.e. like (a/h)^3.
  const ContactResult thick = solve_coated(coating, 10 * a0);
  const ContactResult thicker = solve_coated(coating, 100 * a0);
  const double d_thick = relative(thick.max_pressure, as_coating.max_pressure);
  const double d_thicker = relative(thicker.max_pressure, as_coating.max_pressure);
  INFO("peak pressure distance to the coating's solution: h = 10a " << d_thick << ", 100a "
                                                                    << d_thicker);
  CHECK(d_thicker < 0.01 * d_thick);
  CHECK(d_thicker < 1e-6);

  // h/a -> 0: the coating is a thin skin whose effect falls with h: measured 1.6e-2 at
  // h = 1e-2 a0 and 1.9e-3 at 1e-3 a0 (about linear in h).
  const ContactResult thin = solve_coated(coating, 1e-2 * a0);
  const ContactResult thinner = solve_coated(coating, 1e-3 * a0);
  const double t_thin = relative(thin.max_pressure, as_substrate.max_pressure);
  const double t_thinner = relative(thinner.max_pressure, as_substrate.max_pressure);
  INFO("peak pressure distance to the substrate's solution: h = 1e-2 a " << t_thin << ", 1e-3 a "
                                                                         << t_thinner);
  CHECK(t_thinner < 0.2 * t_thin);
  CHECK(t_thinner < 5e-3);
  // Both limits against the closed forms too: each homogeneous numerical solution is within
  // its discretisation error (1% at a/dx = 16) of Hertz.
  const double Ec = coating.plane_strain_modulus(), Es = kSubstrate.plane_strain_modulus();
  CHECK(relative(as_coating.max_pressure, hertz_sphere_for_load(kLoad, kRadius, Ec).max_pressure) <
        0.01);
  CHECK(relative(as_substrate.max_pressure,
                 hertz_sphere_for_load(kLoad, kRadius, Es).max_pressure) < 0.01);
}
