// Reduced models (model/body_reduction.hpp): where a coating is reduced, the estimated effect
// must bound the true difference of the displacements (the full body by frf-split at a kernel
// tolerance of 1e-12, against the reduced one); where the effect exceeds the budget, the body
// must be kept. The true differences are those of the discrete operators on the scene's grid,
// an independent computation from the Fourier bound of the estimate.
#include <catch2/catch.hpp>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "model/body_reduction.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

LayerStack coated(const Material& m, double h) {
  return LayerStack({Coating{m, h, Interface::bonded}}, steel);
}

// max |u_reduced - u_full| / max |u_full| on 64^2 cells over 3 mm under `p`.
double true_effect(const LayerStack& full, const LayerStack& reduced, const Field& p,
                   const Grid& grid) {
  OperatorOptions o;
  o.method = Method::frf_split;
  o.split.tolerance = 1e-12;
  Field u_full, u_red;
  make_operator(grid, full, o).op->apply(p, u_full);
  make_operator(grid, reduced, o).op->apply(p, u_red);
  return (u_red - u_full).abs().maxCoeff() / u_full.abs().maxCoeff();
}

const Grid kGrid(64, 64, 3e-3, 3e-3);
const ReferenceLoad hertz_1mm{AxisymmetricLoad::hertz, 1e-3};

}  // namespace

TEST_CASE("a coating far thinner than the load is reduced to the substrate, with a bound",
          "[reduction]") {
  const LayerStack body = coated(tin, 0.2e-6);
  const BodyReduction r = reduce_body(body, {hertz_1mm}, 1e-3);
  REQUIRE(r.kind == "substrate");
  REQUIRE(r.body.is_homogeneous());
  CHECK(r.body.substrate() == steel);
  const Field p = hertz_pressure(kGrid, 1e9, 1e-3, Sampling::cell_average);
  const double truth = true_effect(body, r.body, p, kGrid);
  INFO("estimated " << r.estimated_effect << ", true " << truth);
  // Measured: 6.4e-5 true, 5.0e-4 estimated (the bound takes |dH| |P| with no cancellation).
  CHECK(r.estimated_effect >= truth);
  CHECK(r.estimated_effect <= 20 * truth);
  CHECK(r.estimated_effect <= 1e-3);
}

TEST_CASE("a coating whose effect exceeds the budget is kept", "[reduction]") {
  // TiN 2 um changes u by 6.4e-4 of max |u| under this load: reducing it at 1e-4 would be wrong.
  const LayerStack body = coated(tin, 2e-6);
  const Field p = hertz_pressure(kGrid, 1e9, 1e-3, Sampling::cell_average);
  const double truth = true_effect(body, LayerStack(steel), p, kGrid);
  REQUIRE(truth > 1e-4);
  const BodyReduction r = reduce_body(body, {hertz_1mm}, 1e-4);
  CHECK(r.kind == "none");
  CHECK(r.body.coatings().size() == 1);
  CHECK(r.estimated_effect == 0.0);
  // Every reduction tried was estimated above the truth it would have caused.
  for (const auto& [kind, effect] : r.tried) CHECK(effect > 1e-4);
  // A compliant polymer coating is never reduced at 1e-2.
  CHECK(reduce_body(coated(Material(3e9, 0.35), 10e-6), {hertz_1mm}, 1e-2).kind == "none");
}

TEST_CASE("a coating thick against the domain becomes its half-space, with a bound",
          "[reduction]") {
  const LayerStack body = coated(tin, 30e-3);
  const BodyReduction r = reduce_body(body, {hertz_1mm}, 0.05);
  REQUIRE(r.kind == "top_half_space");
  CHECK(r.body.substrate() == tin);
  const Field p = hertz_pressure(kGrid, 1e9, 1e-3, Sampling::cell_average);
  const double truth = true_effect(body, r.body, p, kGrid);
  INFO("estimated " << r.estimated_effect << ", true " << truth);
  CHECK(r.estimated_effect >= truth);  // 1.4e-2 true: the bound is tight here, with its margin
  CHECK(r.estimated_effect <= 2 * truth);
  CHECK(reduce_body(body, {hertz_1mm}, 1e-2).kind == "none");  // 1.4e-2 > 1e-2: kept
}

TEST_CASE("the effect bound holds for a uniform disk, and the largest over loads is used",
          "[reduction]") {
  const LayerStack body = coated(tin, 0.2e-6);
  const ReferenceLoad disk{AxisymmetricLoad::uniform_disk, 1e-3};
  const double e_disk = reduction_effect(*make_frf(body), *make_frf(LayerStack(steel)), disk);
  const Field p = uniform_disk_pressure(kGrid, 1e9, 1e-3, Sampling::cell_average);
  const double truth = true_effect(body, LayerStack(steel), p, kGrid);
  INFO("estimated " << e_disk << ", true " << truth);
  CHECK(e_disk >= truth);
  // The disk's edge makes the thin coating's effect larger than under Hertz: with both loads the
  // reduction must use the disk's (larger) effect.
  const BodyReduction both = reduce_body(body, {hertz_1mm, disk}, 0.1);
  CHECK(both.estimated_effect == Approx(e_disk).epsilon(1e-12));
}

TEST_CASE("layers elastically equal to the medium below are merged exactly", "[reduction]") {
  // Two identical TiN layers are one layer of their total thickness: the FRFs agree to rounding.
  const LayerStack two(
      {Coating{tin, 1e-6, Interface::bonded}, Coating{tin, 1e-6, Interface::bonded},
       Coating{Material(279e9, 0.21), 5e-6, Interface::bonded}},
      steel);
  const BodyReduction r = reduce_body(two, {hertz_1mm}, 1e-9);
  REQUIRE(r.kind == "merged");
  REQUIRE(r.body.coatings().size() == 2);
  CHECK(r.body.coatings()[0].thickness == Approx(2e-6));
  CHECK(r.estimated_effect < 1e-9);
  // A coating of the substrate's own material joins the substrate.
  const BodyReduction same = reduce_body(coated(steel, 5e-6), {hertz_1mm}, 1e-9);
  CHECK(same.kind == "substrate");
  CHECK(same.estimated_effect < 1e-9);
}

TEST_CASE("reduce_body refuses a bad budget and keeps a homogeneous body", "[reduction]") {
  CHECK_THROWS_AS(reduce_body(coated(tin, 1e-6), {hertz_1mm}, 0.0), InvalidArgument);
  CHECK_THROWS_AS(reduce_body(coated(tin, 1e-6), {}, 1e-3), InvalidArgument);
  CHECK(reduce_body(LayerStack(steel), {hertz_1mm}, 1e-3).kind == "none");
}

TEST_CASE("a coating far thinner than the load is reduced by the closed-form bound alone",
          "[reduction][closed_form]") {
  // 1 nm to 1e-20 m of TiN under a 1 mm Hertz load: a / h >= 1e6 is beyond accurate_work_limit,
  // so the Hankel reference (about 10 a / h panels) is never started and no integral is
  // computed.
  for (const double h : {1e-9, 1e-10, 1e-11, 1e-12, 1e-15, 1e-20}) {
    INFO("h = " << h);
    const BodyReduction r = reduce_body(coated(tin, h), {hertz_1mm}, 0.9e-4);
    CHECK(r.kind == "substrate");
    CHECK(r.body.substrate() == steel);
    CHECK(r.work.quadratures == 0);
    CHECK(r.work.frf_evaluations > 0);
    CHECK(r.work.frf_evaluations <= 4001);
    CHECK(r.estimated_effect <= 0.9e-4);
    // The bound is first order in h / a (to a logarithm), down to rounding.
    CHECK(r.estimated_effect <= std::max(1e-4 * h / 1e-9, 1e-12));
  }
}

TEST_CASE("the closed-form bound bounds the accurate one where both are computed",
          "[reduction][closed_form]") {
  const std::unique_ptr<Frf> substrate = make_frf(LayerStack(steel));
  for (const double h : {0.2e-6, 2e-6, 20e-6})
    for (const AxisymmetricLoad shape : {AxisymmetricLoad::hertz, AxisymmetricLoad::uniform_disk}) {
      const LayerStack body = coated(tin, h);
      const ReferenceLoad load{shape, 1e-3};
      const double accurate = reduction_effect(*make_frf(body), *substrate, load);
      long evaluations = 0;
      const double closed = substrate_effect_bound(body, load, &evaluations);
      INFO("h = " << h << ", accurate " << accurate << ", closed form " << closed);
      CHECK(closed >= accurate);
      CHECK(closed <= 10 * accurate);
      CHECK(evaluations <= 4001);
    }
  // A soft coating (polymer on steel: the FRF rises 70-fold) is bounded too.
  const LayerStack polymer = coated(Material(3e9, 0.35), 1e-6);
  CHECK(substrate_effect_bound(polymer, hertz_1mm) >=
        reduction_effect(*make_frf(polymer), *substrate, hertz_1mm));
}

TEST_CASE("the closed-form bound holds on the grid for an unresolved coating",
          "[reduction][closed_form]") {
  // The discrete operators' difference (frf-spectral on both bodies: the same lattice of the
  // FRFs, so the difference is the FRFs') under the cell-averaged load stays within the bound.
  const LayerStack body = coated(tin, 1e-9);
  const BodyReduction r = reduce_body(body, {hertz_1mm}, 0.9e-4);
  REQUIRE(r.kind == "substrate");
  OperatorOptions o;
  o.method = Method::frf_spectral;
  Field u_full, u_sub;
  const Field p = hertz_pressure(kGrid, 1e9, 1e-3, Sampling::cell_average);
  make_operator(kGrid, body, o).op->apply(p, u_full);
  make_operator(kGrid, LayerStack(steel), o).op->apply(p, u_sub);
  const double truth = (u_sub - u_full).abs().maxCoeff() / u_full.abs().maxCoeff();
  INFO("estimated " << r.estimated_effect << ", lattice difference " << truth);
  CHECK(truth <= r.estimated_effect);
}

TEST_CASE("a coating at the resolvable limit still takes the accurate bound",
          "[reduction][closed_form]") {
  // One coating, one load, a / h = 1.96e4 <= accurate_work_limit: the Hankel reference is
  // computed (about 2e5 panels).
  const BodyReduction at = reduce_body(coated(tin, 0.51e-7), {hertz_1mm}, 1e-3);
  CHECK(at.kind == "substrate");
  CHECK(at.work.quadratures > 0);
  // Just beyond (a / h = 2.04e4), the closed form decides.
  const BodyReduction beyond = reduce_body(coated(tin, 0.49e-7), {hertz_1mm}, 1e-3);
  CHECK(beyond.kind == "substrate");
  CHECK(beyond.work.quadratures == 0);
  CHECK(beyond.estimated_effect >= at.estimated_effect * 0.49 / 0.51);
  // The limit counts the coatings and the loads: two loads of 1 mm on 0.2 um (existing cases
  // above: 1e4) stay accurate; on two coatings of 0.1 um (4e4) they do not.
  const ReferenceLoad disk{AxisymmetricLoad::uniform_disk, 1e-3};
  CHECK(reduce_body(coated(tin, 0.2e-6), {hertz_1mm, disk}, 0.1).work.quadratures > 0);
  const LayerStack two({Coating{tin, 0.1e-6, Interface::bonded},
                        Coating{Material(279e9, 0.21), 0.1e-6, Interface::bonded}},
                       steel);
  CHECK(reduce_body(two, {hertz_1mm, disk}, 0.1).work.quadratures == 0);
  // Where the closed form exceeds the budget, the effect bounds run against its lower bound of
  // u(0), with a bounded number of evaluations (docs/auto.md, section 2, "Work"): 1 nm under a
  // load one 47 um cell wide at 1e-6.
  const ReferenceLoad cell{AxisymmetricLoad::hertz, kGrid.dx()};
  const BodyReduction strict = reduce_body(coated(tin, 1e-9), {cell, hertz_1mm}, 1e-6);
  CHECK(strict.kind == "none");
  CHECK(strict.work.quadratures > 0);
  CHECK(strict.work.frf_evaluations <= 2 * 4001 + 4 * 147 * 8379 * 2);
}
