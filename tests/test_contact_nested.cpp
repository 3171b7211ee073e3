// The contact solver's coarse-to-fine start and its conjugation: the Galerkin coarse operators
// (SurfaceOperator::coarsened) against their definition R K P on the fine operator, the grid
// transfers, and the same converged contact whatever the start and the conjugation.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "contact/complementarity.hpp"
#include "contact/contact_solver.hpp"
#include "contact/detail/contact_patches.hpp"
#include "contact/detail/grid_transfer.hpp"
#include "contact/indenter.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/norms.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "tests/rough_test_gap.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

const Material kSteel(210e9, 0.3);
const LayerStack kCoated({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSteel);

Field random_field(std::ptrdiff_t nx, std::ptrdiff_t ny, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Field f(nx, ny);
  for (double& v : f.reshaped()) v = uniform(rng);
  return f;
}

// The definition of the Galerkin coarse operator: K_c p = R K P p on the fine operator.
void check_galerkin(SurfaceOperator& fine, unsigned seed) {
  const auto coarse = fine.coarsened();
  REQUIRE(coarse);
  CHECK(coarse->grid().nx() == fine.grid().nx() / 2);
  CHECK(coarse->grid().ny() == fine.grid().ny() / 2);
  CHECK(coarse->grid().lx() == fine.grid().lx());
  CHECK(coarse->periodic() == fine.periodic());
  CHECK(coarse->method() == fine.method());
  const Field p = random_field(coarse->grid().nx(), coarse->grid().ny(), seed);
  const Field reference = detail::restrict_by_mean(fine.apply(detail::prolong_by_cell(p)));
  // Both sides are sums of the same coefficients in another order: rounding only (two FFT
  // round trips of about 1e-15 each, against displacements of one sign).
  CHECK(rel_linf(coarse->apply(p), reference) <= 1e-12);
}

}  // namespace

TEST_CASE("Grid transfers: the 2 x 2 mean undoes the cell-wise prolongation", "[contact][nested]") {
  const Field c = random_field(5, 3, 7);
  const Field f = detail::prolong_by_cell(c);
  REQUIRE(f.rows() == 10);
  REQUIRE(f.cols() == 6);
  CHECK(f(9, 5) == c(4, 2));
  CHECK(f(4, 1) == c(2, 0));
  // A pressure keeps its force: four fine cells of a quarter the area each.
  CHECK(std::abs(f.sum() - 4 * c.sum()) <= 1e-13 * f.sum());
  CHECK(rel_linf(detail::restrict_by_mean(f), c) <= 1e-15);
  Field ramp(4, 2);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) ramp(i, j) = i + 4 * j;
  const Field mean = detail::restrict_by_mean(ramp);
  REQUIRE(mean.rows() == 2);
  REQUIRE(mean.cols() == 1);
  CHECK(mean(0, 0) == Approx(0.25 * (0 + 1 + 4 + 5)));
  CHECK(mean(1, 0) == Approx(0.25 * (2 + 3 + 6 + 7)));
}

TEST_CASE("Contact patches: edge-connected pieces, joined across a periodic border",
          "[contact][nested]") {
  detail::CellMask cells = detail::CellMask::Constant(6, 5, false);
  CHECK(detail::count_patches(cells, false) == 0);
  cells(0, 0) = cells(1, 0) = cells(1, 1) = true;  // one L-shaped patch
  cells(3, 3) = true;                              // touches the first only at no edge
  cells(4, 4) = true;                              // diagonal to (3, 3): a patch of its own
  cells(5, 0) = true;                              // beside (0, 0) across the x border
  CHECK(detail::count_patches(cells, false) == 4);
  CHECK(detail::count_patches(cells, true) == 3);
  cells(0, 4) = true;  // beside (0, 0) across the y border
  CHECK(detail::count_patches(cells, false) == 5);
  CHECK(detail::count_patches(cells, true) == 3);
  CHECK(detail::count_patches(detail::CellMask::Constant(4, 4, true), true) == 1);
}

TEST_CASE("Galerkin coarse operators equal R K P on the fine grid", "[contact][nested]") {
  SECTION("periodic, half-space and coated") {
    const Grid grid(32, 24, 1e-3, 0.8e-3);
    for (const LayerStack& body : {LayerStack(kSteel), kCoated}) {
      PeriodicOperator op(grid, periodic_influence_kernel(grid, *make_frf(body)), Method::dcfft);
      check_galerkin(op, 11);
    }
  }
  SECTION("DC-FFT, Love's coefficients on an oblong grid") {
    const Grid grid(24, 20, 1e-3, 1.5e-3);
    DcfftOperator op(love_kernel(grid, 1e11));
    check_galerkin(op, 13);
  }
  SECTION("no coarse form: an odd side, or an operator kind without one") {
    const Grid odd(24, 21, 1e-3, 1e-3);
    DcfftOperator dcfft(love_kernel(odd, 1e11));
    CHECK_FALSE(dcfft.coarsened());
    const Grid even(8, 8, 1e-3, 1e-3);
    DirectOperator direct(love_kernel(even, 1e11));
    CHECK_FALSE(direct.coarsened());
  }
}

TEST_CASE("Nested start and either conjugation reach the same contact", "[contact][nested]") {
  // Rough contacts of several patches on 128^2 (one coarse level): coated and periodic, a
  // half-space with a free surface on DC-FFT.
  const bool periodic = GENERATE(true, false);
  const ContactControl control = GENERATE(ContactControl::load, ContactControl::approach);
  const Grid grid(128, 128, 1e-3, 1e-3);
  const Field h = test::rough_test_gap(grid, 8, 5);
  std::unique_ptr<SurfaceOperator> op;
  if (periodic) {
    op = std::make_unique<PeriodicOperator>(
        grid, periodic_influence_kernel(grid, *make_frf(kCoated)), Method::frf_split);
  } else {
    op = std::make_unique<DcfftOperator>(love_kernel(grid, kSteel.plane_strain_modulus()));
  }
  // About 5 % contact: a mean pressure of 0.05 E* times the rms slope, or a fifth of the way
  // down to the mean height.
  const double value = control == ContactControl::load
                           ? 0.05 * kSteel.plane_strain_modulus() * 0.05 * 1e-6
                           : h.minCoeff() + 0.2 * (h.mean() - h.minCoeff());
  ContactOptions before;  // Polonsky & Keer's conjugation from the Hertzian start
  before.conjugation = Conjugation::polonsky_keer;
  before.nested_start = false;
  ContactOptions flat = ContactOptions{};
  flat.nested_start = false;
  const ContactResult reference = ContactSolver(*op, before).solve(h, control, value);
  const ContactResult single = ContactSolver(*op, flat).solve(h, control, value);
  const ContactResult nested = ContactSolver(*op).solve(h, control, value);
  INFO((periodic ? "periodic" : "DC-FFT") << ": iterations " << reference.iterations << ", "
                                          << single.iterations << ", " << nested.iterations);
  REQUIRE(reference.converged);
  REQUIRE(single.converged);
  REQUIRE(nested.converged);
  CHECK(reference.coarse_applications == 0);
  CHECK(single.coarse_applications == 0);
  CHECK(nested.coarse_applications > 0);
  // One discrete problem, each solved to a relative pressure change of 1e-10: equal to the
  // solver tier, as the other iteration variants (test_contact.cpp).
  CHECK(rel_linf(single.pressure, reference.pressure) <= 1e-8);
  CHECK(rel_linf(nested.pressure, reference.pressure) <= 1e-8);
  CHECK((single.pressure > 0).count() == (reference.pressure > 0).count());
  CHECK((nested.pressure > 0).count() == (reference.pressure > 0).count());
}

TEST_CASE("Hertz at 512^2 within 25 applications: no nested start for one patch",
          "[contact][nested]") {
  const HertzSphere hertz = hertz_sphere_for_load(10.0, 0.01, 1e11);
  const Grid grid(512, 512, 4 * hertz.contact_radius, 4 * hertz.contact_radius);
  DcfftOperator op(love_kernel(grid, 1e11));
  const ContactResult r = ContactSolver(op).solve_load(height(grid, Sphere{0.01}), 10.0);
  INFO(r.iterations << " iterations, " << r.operator_applications << " applications, "
                    << r.coarse_applications << " on the coarser grids");
  REQUIRE(r.converged);
  // One patch: the Hertzian start, no coarse solve (measured 13 iterations, 19 applications).
  CHECK(r.coarse_applications == 0);
  CHECK(r.operator_applications <= 25);
  CHECK(std::abs(r.contact_radius.value() / hertz.contact_radius - 1) <= 0.01);
}

namespace {

// The complementarity conditions on every cell, from a fresh application: g = h + K p - delta,
// delta the approach (load control: the mean of h + K p over the contact, which is what the
// solver's gap is measured from).
void check_complementarity(SurfaceOperator& op, const Field& h, const ContactResult& r,
                           double tolerance) {
  const Field u = op.apply(r.pressure);
  const auto contact = r.pressure > 0;
  const double approach = r.control == ContactControl::load
                              ? contact.select(h + u, 0.0).sum() / contact.count()
                              : r.approach.value();
  const Field g = h + u - approach;
  const double eps = detail::gap_tolerance(
      tolerance, u.abs().maxCoeff(), h.abs().maxCoeff() + u.abs().maxCoeff() + std::abs(approach));
  CHECK((r.pressure >= 0).all());
  CHECK(contact.select(g.abs(), 0.0).maxCoeff() <= eps);
  CHECK((-g).maxCoeff() <= eps);
}

}  // namespace

TEST_CASE("Hard rough contacts converge, and only on a solution", "[contact][nested]") {
  // The nested start and Polak-Ribiere's conjugation on the cases that strain a contact solver:
  // near full contact, a very light load (a few cells), and a soft coating (strong contrast:
  // 1 GPa on steel, 5 um, cells of 7.8 um), on a periodic rough surface of 128^2.
  const Grid grid(128, 128, 1e-3, 1e-3);
  const Field h = test::rough_test_gap(grid, 8, 9);
  const LayerStack soft({{Material(1e9, 0.4), 5e-6, Interface::bonded}}, kSteel);
  const bool soft_coating = GENERATE(false, true);
  const LayerStack& body = soft_coating ? soft : LayerStack(kSteel);
  PeriodicOperator op(grid, periodic_influence_kernel(grid, *make_frf(body)), Method::frf_split);
  const double e_star = kSteel.plane_strain_modulus();
  struct Case {
    const char* name;
    ContactControl control;
    double value;
  };
  const double h_min = h.minCoeff(), h_mean = h.mean();
  for (const Case& c :
       {Case{"near full contact", ContactControl::approach, h_mean - 1e-3 * (h_mean - h_min)},
        Case{"very light load", ContactControl::load, 1e-7 * e_star * 1e-6},
        Case{"moderate load", ContactControl::load, 0.02 * e_star * 0.05 * 1e-6}}) {
    const ContactResult r = ContactSolver(op).solve(h, c.control, c.value);
    INFO((soft_coating ? "soft coating, " : "steel, ")
         << c.name << ": " << to_string(r.status) << " after " << r.iterations
         << " iterations, area fraction " << r.contact_area / 1e-6);
    REQUIRE(r.converged);
    check_complementarity(op, h, r, 1e-10);
  }
}
