// The hardness cap of the contact solver (ContactOptions::hardness): the capped contact against
// an independent solve of the same box-constrained problem (tests/box_qp_reference.hpp), its
// limits (no cap reached: the elastic contact; a low hardness: every carrying cell at it, area
// W / H), and a sphere loaded and unloaded (the dent it keeps).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "layers/layer_stack.hpp"
#include "tests/box_qp_reference.hpp"
#include "tests/rough_test_gap.hpp"
#include "tests/test_materials.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

// A 10 mm steel ball at 5 N on a 0.4 mm square of 48 x 48 cells: a Hertzian radius of about
// 12 cells.
struct CappedBall {
  Grid grid{48, 48, 0.4e-3, 0.4e-3};
  double radius = 10e-3;
  double load = 5.0;
  Field height() const { return coatfft::height(grid, Sphere{radius}); }
  HertzSphere hertz() const {
    return hertz_sphere_for_load(load, radius, steel.plane_strain_modulus());
  }
};

ContactOptions capped(double hardness, double tolerance = 1e-12) {
  ContactOptions o;
  o.tolerance = tolerance;
  o.hardness = hardness;
  return o;
}

}  // namespace

TEST_CASE("Hardness: the capped contact is the box-constrained problem's solution",
          "[contact][hardness]") {
  SECTION("a sphere under load control on bare steel") {
    const CappedBall ball;
    const BuiltOperator built = make_operator(ball.grid, LayerStack(steel), {});
    const double cap = 0.7 * ball.hertz().max_pressure;
    ContactSolver solver(*built.op, capped(cap));
    const Field h = ball.height();
    const ContactResult r = solver.solve_load(h, ball.load);
    REQUIRE(r.converged);
    const test::BoxQpSolution ref =
        test::solve_box_qp(*built.op, h, cap, ContactControl::load, ball.load, 1e-13);
    INFO("reference iterations " << ref.iterations << ", last change " << ref.step_change);
    // Both stop near 1e-12 (the solver's relative pressure change, the reference's step): the
    // same minimiser (K is positive definite) to about that; measured 6e-12.
    CHECK((r.pressure - ref.pressure).abs().maxCoeff() / cap < 1e-10);
    CHECK(r.pressure.maxCoeff() == cap);
    CHECK(r.load == Approx(ball.load).epsilon(1e-12));
  }
  SECTION("a rough periodic surface under approach control on TiN-coated steel") {
    const Grid g(32, 32, 1e-3, 1e-3);
    OperatorOptions o;
    o.boundary = Boundary::periodic;
    const LayerStack body({{tin, 5e-6, Interface::bonded}}, steel);
    const BuiltOperator built = make_operator(g, body, o);
    const Field h = test::rough_test_gap(g, 4, 11);
    const double approach = 0.3 * h.mean();
    const ContactResult elastic = ContactSolver(*built.op).solve_approach(h, approach);
    const double cap = 0.3 * elastic.max_pressure;
    ContactSolver solver(*built.op, capped(cap));
    const ContactResult r = solver.solve_approach(h, approach);
    REQUIRE(r.converged);
    const test::BoxQpSolution ref =
        test::solve_box_qp(*built.op, h, cap, ContactControl::approach, approach, 1e-13);
    INFO("reference iterations " << ref.iterations << ", last change " << ref.step_change);
    CHECK((r.pressure - ref.pressure).abs().maxCoeff() / cap < 1e-10);  // measured 6e-13
  }
}

TEST_CASE("Hardness: a cap no cell reaches gives the elastic contact", "[contact][hardness]") {
  const CappedBall ball;
  const BuiltOperator built = make_operator(ball.grid, LayerStack(steel), {});
  const Field h = ball.height();
  ContactOptions elastic_options;
  elastic_options.tolerance = 1e-12;
  const ContactResult elastic = ContactSolver(*built.op, elastic_options).solve_load(h, ball.load);
  for (const double factor : {1.01, 1e3}) {
    const ContactResult r =
        ContactSolver(*built.op, capped(factor * elastic.max_pressure)).solve_load(h, ball.load);
    REQUIRE(r.converged);
    // The iterates differ by the load's restoration (scaled in place, not deferred): rounding.
    CHECK((r.pressure - elastic.pressure).abs().maxCoeff() < 1e-11 * elastic.max_pressure);
    CHECK(r.plastic_depth.maxCoeff() == 0.0);
    CHECK(r.contact_area == elastic.contact_area);
  }
}

TEST_CASE("Hardness: at a low hardness the load rests on W / H", "[contact][hardness]") {
  const Grid g(64, 64, 1e-3, 1e-3);
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  const BuiltOperator built = make_operator(g, LayerStack(steel), o);
  const Field h = test::rough_test_gap(g, 4, 5);
  const double load = 100.0;
  const ContactResult elastic = ContactSolver(*built.op).solve_load(h, load);
  const double mean_pressure = load / elastic.contact_area;
  for (const double ratio : {0.5, 0.2, 0.05}) {
    INFO("hardness / elastic mean contact pressure = " << ratio);
    const double cap = ratio * mean_pressure;
    const ContactResult r = ContactSolver(*built.op, capped(cap, 1e-10)).solve_load(h, load);
    REQUIRE(r.converged);
    CHECK(r.load == Approx(load).epsilon(1e-12));
    CHECK(r.max_pressure <= cap);
    // Every carrying cell carries at most H: A >= W / H, with equality when all are at H; the
    // cells below H are those on the rims of the plastic spots, fewer as H falls.
    const double plastic_cells = static_cast<double>((r.pressure >= cap).count());
    const double carrying_cells = static_cast<double>((r.pressure > 0).count());
    CHECK(r.contact_area >= load / cap * (1 - 1e-12));
    // Measured at 0.5, 0.2, 0.05: plastic shares 0.70, 0.91, 0.99; A H / W 1.18, 1.05, 1.005.
    if (ratio <= 0.2) CHECK(plastic_cells / carrying_cells > 0.85);
    if (ratio <= 0.05) CHECK(plastic_cells / carrying_cells > 0.98);
    if (ratio <= 0.05) CHECK(r.contact_area < 1.02 * load / cap);
    // The plastic depth is the overlap of the cells at H, and only of those.
    CHECK(((r.pressure < cap) && (r.plastic_depth > 0)).count() == 0);
    CHECK((r.plastic_depth - (r.pressure >= cap).select(-r.gap, 0.0)).abs().maxCoeff() == 0.0);
  }
}

TEST_CASE("Hardness: a coating of the substrate's material gives the half-space",
          "[contact][hardness]") {
  const Grid g(64, 64, 1e-3, 1e-3);
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  const BuiltOperator bare = make_operator(g, LayerStack(steel), o);
  const BuiltOperator coated =
      make_operator(g, LayerStack({{steel, 20e-6, Interface::bonded}}, steel), o);
  const Field h = test::rough_test_gap(g, 4, 5);
  const double load = 5.0;
  const double cap = 0.5 * ContactSolver(*bare.op).solve_load(h, load).max_pressure;
  const ContactResult a = ContactSolver(*bare.op, capped(cap, 1e-10)).solve_load(h, load);
  const ContactResult b = ContactSolver(*coated.op, capped(cap, 1e-10)).solve_load(h, load);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK((a.pressure - b.pressure).abs().maxCoeff() < 1e-6 * cap);
  CHECK(b.plastic_depth.maxCoeff() == Approx(a.plastic_depth.maxCoeff()).epsilon(1e-6));
}

TEST_CASE("Hardness: a sphere loaded and unloaded keeps its dent", "[contact][hardness]") {
  const CappedBall ball;
  const BuiltOperator built = make_operator(ball.grid, LayerStack(steel), {});
  const Field h = ball.height();
  const double cap = 0.6 * ball.hertz().max_pressure;
  ContactOptions options = capped(cap, 1e-11);
  options.compute_approach = true;
  ContactSolver solver(*built.op, options);
  const std::vector<double> loads{1.0, 2.5, 5.0};
  const std::vector<ContactResult> cycle = solver.solve_sweep(h, ContactControl::load, loads, true);
  REQUIRE(cycle.size() == 5);  // 1, 2.5, 5, then 2.5, 1
  for (const ContactResult& r : cycle) REQUIRE(r.converged);
  const std::vector<double> order{1.0, 2.5, 5.0, 2.5, 1.0};
  for (std::size_t k = 0; k < cycle.size(); ++k)
    CHECK(cycle[k].load == Approx(order[k]).epsilon(1e-12));
  // The depth never decreases, and grows only while loading.
  for (std::size_t k = 1; k < cycle.size(); ++k)
    CHECK((cycle[k].plastic_depth - cycle[k - 1].plastic_depth).minCoeff() >= 0.0);
  const Field& peak = cycle[2].plastic_depth;
  CHECK(peak.maxCoeff() > 0.0);
  CHECK((cycle[4].plastic_depth - peak).abs().maxCoeff() < 1e-9 * peak.maxCoeff());
  // Unloading is elastic: the last step is the elastic contact of the dented surface.
  ContactOptions elastic_options;
  elastic_options.tolerance = 1e-11;
  const Field dented = h + peak;
  const ContactResult elastic = ContactSolver(*built.op, elastic_options).solve_load(dented, 1.0);
  CHECK((cycle[4].pressure - elastic.pressure).abs().maxCoeff() < 1e-8 * elastic.max_pressure);
  // The dent conforms: at the same load the unloading contact is wider and flatter.
  CHECK(cycle[4].contact_area > cycle[0].contact_area);
  CHECK(cycle[4].max_pressure < cycle[0].max_pressure);
}

TEST_CASE("Hardness: refusals", "[contact][hardness]") {
  const CappedBall ball;
  const BuiltOperator built = make_operator(ball.grid, LayerStack(steel), {});
  for (const double bad : {0.0, -1.0, std::nan(""), HUGE_VAL})
    CHECK_THROWS_WITH(ContactSolver(*built.op, capped(bad)),
                      Catch::Contains("hardness") && Catch::Contains("finite and > 0"));
  ContactSolver solver(*built.op, capped(1e6));
  // 1 MPa over 0.4 x 0.4 mm carries at most 0.16 N.
  CHECK_THROWS_WITH(solver.solve_load(ball.height(), 0.2),
                    Catch::Contains("below the hardness times the domain's area"));
}
