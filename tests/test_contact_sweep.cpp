// Load and approach sweeps (ContactSolver::solve_sweep): each value's solution is the one a solve
// of its own gives (the start changes the path, not the discrete solution), and the warm starts
// cost fewer operator applications than cold solves.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "contact/contact_solver.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "surfaces/self_affine_surface.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

// A rigid flat on a periodic self-affine surface (shortest wavelength 8 cells): many contact
// spots that grow and merge with the load.
Field flat_on_rough_surface(const Grid& g) {
  SelfAffineSpec spec;
  spec.rms_slope = 0.05;
  spec.short_cutoff = 8 * g.dx();
  spec.seed = 7;
  const Field z = self_affine_surface(g, spec);
  return z.maxCoeff() - z;
}

}  // namespace

TEST_CASE("solve_sweep: the solutions of the solves one by one, for fewer applications",
          "[contact_sweep]") {
  const Grid g(64, 64, 1e-3, 1e-3);
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  const BuiltOperator built = make_operator(g, LayerStack(steel), o);
  ContactSolver solver(*built.op);
  const Field gap = flat_on_rough_surface(g);
  // 1 % to about 30 % of the cells in contact, given out of order.
  std::vector<double> loads;
  for (int k = 0; k < 12; ++k) loads.push_back(25.0 * std::pow(30.0, k / 11.0));
  std::reverse(loads.begin(), loads.end());
  const std::vector<ContactResult> sweep = solver.solve_sweep(gap, ContactControl::load, loads);
  std::sort(loads.begin(), loads.end());
  REQUIRE(sweep.size() == loads.size());
  int cold_applications = 0, sweep_applications = 0;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    INFO("load " << loads[k]);
    const ContactResult cold = solver.solve_load(gap, loads[k]);
    REQUIRE(cold.converged);
    REQUIRE(sweep[k].converged);
    CHECK(sweep[k].load == Approx(loads[k]).epsilon(1e-12));
    // Both stop at a relative pressure change of 1e-10: the same solution to a few times that.
    CHECK((sweep[k].pressure - cold.pressure).abs().maxCoeff() < 1e-8 * cold.max_pressure);
    cold_applications += cold.operator_applications;
    sweep_applications += sweep[k].operator_applications;
  }
  // The property a sweep exists for (bench/bench_load_sweep.cpp measures it at 256^2 and 512^2).
  INFO("applications: cold " << cold_applications << ", sweep " << sweep_applications);
  CHECK(sweep_applications < 0.9 * cold_applications);
}

TEST_CASE("solve_sweep under approach control, and its refusals", "[contact_sweep]") {
  const Grid g(32, 32, 1e-3, 1e-3);
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  const BuiltOperator built = make_operator(g, LayerStack(steel), o);
  ContactSolver solver(*built.op);
  const Field gap = flat_on_rough_surface(g);
  const double mean = gap.mean();
  const std::vector<double> approaches{0.1 * mean, 0.2 * mean, 0.3 * mean};
  const std::vector<ContactResult> sweep =
      solver.solve_sweep(gap, ContactControl::approach, approaches);
  for (std::size_t k = 0; k < approaches.size(); ++k) {
    const ContactResult cold = solver.solve_approach(gap, approaches[k]);
    REQUIRE(sweep[k].converged);
    CHECK((sweep[k].pressure - cold.pressure).abs().maxCoeff() < 1e-8 * cold.max_pressure);
    CHECK(*sweep[k].approach == Approx(approaches[k]).epsilon(1e-14));
  }
  // A repeated value is solved twice, to the same solution.
  const std::vector<ContactResult> twice =
      solver.solve_sweep(gap, ContactControl::load, {20.0, 10.0, 10.0, 20.0});
  REQUIRE(twice.size() == 4);
  for (const ContactResult& r : twice) CHECK(r.converged);
  CHECK((twice[1].pressure - twice[0].pressure).abs().maxCoeff() < 1e-8 * twice[0].max_pressure);
  CHECK((twice[3].pressure - twice[2].pressure).abs().maxCoeff() < 1e-8 * twice[2].max_pressure);
  // Every value is checked before the first solve, an approach against the heights too.
  CHECK_THROWS_AS(
      solver.solve_sweep(gap, ContactControl::approach, {0.1 * mean, 2 * gap.maxCoeff()}),
      InvalidArgument);
  CHECK_THROWS_AS(solver.solve_sweep(gap, ContactControl::load, {}), InvalidArgument);
  CHECK_THROWS_AS(solver.solve_sweep(gap, ContactControl::load, {10.0, -1.0}), InvalidArgument);
  CHECK_THROWS_AS(solver.solve_sweep(gap, ContactControl::load, {10.0, NAN}), InvalidArgument);
}
