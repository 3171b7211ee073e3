// The sliding contact (contact/sliding_contact.hpp): without friction it is the plain solve; with
// a coupling that vanishes (an incompressible half-space, nu = 1/2) one extra solve changes
// nothing; on steel under a rigid sphere the pressure moves to the trailing side (the surface
// ahead of the tractions sinks: Betti's reciprocity with Boussinesq's inward radial
// displacement), by an amount of the order of beta mu (Johnson 1985, section 7.2).
#include <catch2/catch.hpp>
#include <cmath>

#include "contact/indenter.hpp"
#include "contact/sliding_contact.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "core/error.hpp"
#include "tests/test_materials.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

constexpr double kSphereRadius = 0.01, kNormalLoad = 20.0;

// The x coordinate of the pressure's centroid [m].
double centroid_x(const Grid& g, const Field& p) {
  double m = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) m += g.x(i) * p(i, j);
  return m / p.sum();
}

}  // namespace

TEST_CASE("sliding contact: the coupling iterated to its fixed point", "[contact][sliding]") {
  const double a = hertz_sphere_for_load(kNormalLoad, kSphereRadius, steel.plane_strain_modulus())
                       .contact_radius;
  const Grid g(49, 49, 4 * a, 4 * a);
  DcfftOperator op(love_kernel(g, steel.plane_strain_modulus()));
  ContactSolver solver(op);
  const Field h = height(g, Sphere{kSphereRadius});
  CerrutiOperator cerruti(g, steel);
  const TangentialCoupling coupling = [&](const Field& qx) {
    std::array<Field, 3> u;
    cerruti.apply(Field::Zero(qx.rows(), qx.cols()), &qx, nullptr, u);
    return u[2];
  };
  const ContactResult plain = solver.solve(h, ContactControl::load, kNormalLoad);

  SlidingReport r;
  const ContactResult none =
      solve_sliding(solver, coupling, h, ContactControl::load, kNormalLoad, {0.0, 1e-9, 30}, &r);
  CHECK(r.solves == 1);
  CHECK((none.pressure == plain.pressure).all());

  const double mu = 0.25, beta = (1 - 2 * 0.3) / (2 * (1 - 0.3));
  const ContactResult slid =
      solve_sliding(solver, coupling, h, ContactControl::load, kNormalLoad, {mu, 1e-9, 30}, &r);
  INFO("solves " << r.solves << ", shift " << r.pressure_shift);
  CHECK(r.converged);
  CHECK(r.pressure_change <= 1e-9);
  CHECK(r.solves >= 4);  // a contraction by about beta mu = 0.07 per solve from 1 to 1e-9
  // The largest change sits at the contact's moving rim and grows as cells resolve it (2.1 beta
  // mu at 65^2, 3.2 at 257^2: docs/validation/traction.md); the centroid's shift does not
  // (-0.48 beta mu a on every grid there).
  CHECK(r.pressure_shift > 0.3 * beta * mu);
  CHECK(r.pressure_shift < 3.0 * beta * mu);
  const double shift = centroid_x(g, slid.pressure) - centroid_x(g, plain.pressure);
  CHECK(r.centroid_shift == Approx(shift).epsilon(1e-12));
  CHECK(shift < -0.35 * beta * mu * a);  // towards the trailing side
  CHECK(shift > -0.6 * beta * mu * a);
  CHECK(slid.load == Approx(kNormalLoad).epsilon(1e-9));
  // The displacement returned includes the tractions' share of the final pressure.
  CHECK((slid.displacement - (op.apply(slid.pressure) + coupling(mu * slid.pressure)))
            .abs()
            .maxCoeff() < 1e-12 * slid.displacement.abs().maxCoeff());

  // A coupling that vanishes (nu = 1/2 has C = 0): one more solve, the same pressure.
  const TangentialCoupling zero = [](const Field& qx) {
    return Field(Field::Zero(qx.rows(), qx.cols()));
  };
  const ContactResult same =
      solve_sliding(solver, zero, h, ContactControl::load, kNormalLoad, {mu, 1e-9, 30}, &r);
  CHECK(r.solves == 2);
  CHECK(r.pressure_shift == 0.0);

  // Two solves cannot reach 1e-9 at a contraction of 0.07: the coupling, not the normal solver,
  // ran out, and the status names it.
  const ContactResult cut =
      solve_sliding(solver, coupling, h, ContactControl::load, kNormalLoad, {mu, 1e-9, 2}, &r);
  CHECK(r.solves == 2);
  CHECK_FALSE(r.converged);
  CHECK_FALSE(cut.converged);
  CHECK(cut.status == ContactStatus::coupling_limit);
  CHECK(to_string(cut.status) == "coupling_limit");
  CHECK_THAT(cut.warning, Catch::Contains("friction coupling did not converge in 2 normal solves"));

  CHECK_THROWS_AS(
      solve_sliding(solver, coupling, h, ContactControl::load, kNormalLoad, {-0.1, 1e-9, 30}),
      InvalidArgument);
  CHECK_THROWS_AS(
      solve_sliding(solver, coupling, h, ContactControl::load, kNormalLoad, {mu, 0.0, 30}),
      InvalidArgument);
}
