// Polonsky-Keer contact solver (contact/contact_solver.hpp) against Hertz and the flat punch on
// DC-FFT, plus its own consistency properties and its input checks.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "convolution/operators/detail/frf_spectral_operator.hpp"
#include "core/error.hpp"
#include "core/norms.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "validation/hertz_contact.hpp"

using namespace coatfft;

namespace {

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

constexpr double kModulus = 1e11;  // E* [Pa]
constexpr double kRadius = 0.01;   // sphere radius [m]
constexpr double kLoad = 10.0;     // [N]; a = 90.9 um, a/R = 0.009

// A Hertz problem on [-2a, 2a]^2: the contact covers half the width, and the domain edge sits where
// the pressure is zero anyway (DC-FFT has no periodic images, so no larger margin is needed).
struct HertzProblem {
  HertzSphere reference = hertz_sphere_for_load(kLoad, kRadius, kModulus);
  Grid grid;
  Field h;
  explicit HertzProblem(std::ptrdiff_t n)
      : grid(n, n, 4 * reference.contact_radius, 4 * reference.contact_radius),
        h(height(grid, Sphere{kRadius})) {}
};

// The model of an error in g(0), the zero-frequency sample of a spectral operator: it adds one
// constant to every displacement, proportional to the total force, u -> u + c sum(p) dx dy.
class OffsetOperator final : public SurfaceOperator {
 public:
  OffsetOperator(SurfaceOperator& inner, double c) : inner_(inner), c_(c) {}
  const Grid& grid() const override { return inner_.grid(); }
  void apply(const Field& p, Field& u) override {
    inner_.apply(p, u);
    u += c_ * p.sum() * grid().dx() * grid().dy();
  }
  coatfft::Method method() const override { return inner_.method(); }
  using SurfaceOperator::apply;

 private:
  SurfaceOperator& inner_;
  double c_;
};

}  // namespace

TEST_CASE("Hertz sphere on DC-FFT: radius, peak pressure and approach", "[contact][hertz]") {
  const std::ptrdiff_t n = GENERATE(64, 128);
  const bool preconditioned = GENERATE(true, false);
  const HertzProblem hp(n);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.compute_approach = true;
  opts.preconditioned = preconditioned;
  ContactSolver solver(op, opts);
  const ContactResult res = solver.solve_load(hp.h, kLoad);
  INFO("n = " << n << ", preconditioned = " << preconditioned << ", iterations = " << res.iterations
              << ", residual = " << res.residual);
  REQUIRE(res.converged);
  REQUIRE(res.contact_radius.has_value());
  REQUIRE(res.approach.has_value());
  const double a = hp.reference.contact_radius;
  const double dx = hp.grid.dx();
  // Contact radius from the area, sqrt(A/pi): the contact set is a union of cells, so its edge is
  // resolved to a fraction of a cell: |a_num - a| <= dx/2 (measured 0.48% = 0.08 dx at n = 64,
  // 0.54% = 0.17 dx at n = 128).
  CHECK(std::abs(*res.contact_radius - a) <= 0.5 * dx);
  // Peak pressure and approach: DC-FFT is exact for piecewise-constant pressure, so the error is
  // the O(dx^2) of that representation of the smooth Hertz field (measured p0: -8.7e-4, -2.0e-4;
  // approach: -2.2e-4, -4.3e-5 at n = 64, 128, i.e. <= 0.22 (dx/a)^2). Tolerance 0.5 (dx/a)^2.
  const double tol2 = 0.5 * (dx / a) * (dx / a);
  CHECK(std::abs(res.max_pressure / hp.reference.max_pressure - 1) <= tol2);
  CHECK(std::abs(*res.approach / hp.reference.approach - 1) <= tol2);
  // Pointwise pressure against p0 sqrt(1 - r^2/a^2): the cells of the ring r ~ a carry an error of
  // order p0 sqrt(dx/a) on an area ~ a dx, so the relative l2 error is O(dx/a) (measured 9.1e-3
  // and 4.5e-3, i.e. 0.15 dx/a). Tolerance 0.3 dx/a.
  Field p_ref(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      p_ref(i, j) = hp.reference.pressure(std::hypot(hp.grid.x(i), hp.grid.y(j)));
    }
  }
  CHECK(rel_l2(res.pressure, p_ref) <= 0.3 * dx / a);
}

TEST_CASE("Solver constraints: load balance, p >= 0, complementary gap", "[contact]") {
  const HertzProblem hp(64);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.compute_approach = true;
  opts.preconditioned = GENERATE(true, false);
  // The default tolerance, and the tighter one at which the gap meets -1e-12 delta (below).
  opts.tolerance = GENERATE(1e-10, 1e-12);
  INFO("preconditioned = " << opts.preconditioned << ", tolerance = " << opts.tolerance);
  const ContactResult res = ContactSolver(op, opts).solve_load(hp.h, kLoad);
  REQUIRE(res.converged);
  // The load is imposed by a rescaling in every iteration: exact up to rounding of the sum.
  CHECK(std::abs(res.load / kLoad - 1) <= 1e-10);
  CHECK(std::abs(res.pressure.sum() * hp.grid.dx() * hp.grid.dy() / kLoad - 1) <= 1e-10);
  CHECK(res.pressure.minCoeff() >= 0.0);  // projection: exactly non-negative
  const double delta = *res.approach;
  const Mask contact = res.pressure > 0;
  // Outside the contact the gap is open (the overlap step puts pressure on any cell with g < 0).
  CHECK((!contact).select(res.gap, 1.0).minCoeff() >= -1e-12 * delta);
  // Inside, the gap vanishes to the stopping tolerance: it is the residual of complementarity,
  // and the last relative pressure change tol moves u by a fraction of tol delta. Measured
  // max |g| / delta = 5.5e-12 / 1.0e-11 at tol 1e-10 and 3.6e-14 / 2.0e-13 at tol 1e-12
  // (preconditioned / classic; up to 0.26 tol at 128^2 and 256^2, classic). Bound: tol delta.
  CHECK(contact.select(res.gap.abs(), 0.0).maxCoeff() <= opts.tolerance * delta);
  // Hence gap >= -1e-12 delta on every cell needs a solve to tol ~ 1e-12 (at 1e-10 the contact
  // cells reach -3.1e-12 / -1.0e-11 delta). At 1e-12: measured min g / delta = -3.1e-14
  // (preconditioned), -1.3e-13 (classic); the rounding floor is ~1e-13 (a 128^2 preconditioned
  // solve stalls at -7e-14 however tight the tolerance).
  if (opts.tolerance <= 1e-12) CHECK(res.gap.minCoeff() >= -1e-12 * delta);
  // Gap, displacement and approach are consistent: g = h + u - delta.
  CHECK(rel_linf(res.gap, hp.h + res.displacement - delta) <= 1e-14);
  CHECK_FALSE(res.touches_boundary);
  CHECK(res.warning.empty());
  CHECK(res.contact_area ==
        Approx(static_cast<double>(contact.count()) * hp.grid.dx() * hp.grid.dy()));
}

TEST_CASE("Flat punch: load at a given approach is 2 a E* delta", "[contact][punch]") {
  const std::ptrdiff_t n = GENERATE(64, 128);
  const double a = 1e-3;
  const double delta = 1e-6;
  const Grid grid(n, n, 4 * a, 4 * a);
  const double dx = grid.dx();
  // Edge radius rho = 0.01 dx^2 / delta: the rounded edge rises to h = delta within
  // sqrt(2 rho delta) = 0.14 dx of r = a, so the contact can grow beyond the face only by cells
  // whose centres lie within that sliver: the solve sees a sharp punch of radius a + O(0.14 dx).
  const Field h = height(grid, FlatPunch{a, 0.01 * dx * dx / delta});
  DcfftOperator op(love_kernel(grid, kModulus));
  ContactOptions opts;
  opts.preconditioned = GENERATE(true, false);
  const ContactResult res = ContactSolver(op, opts).solve_approach(h, delta);
  INFO("n = " << n << ", preconditioned = " << opts.preconditioned
              << ", iterations = " << res.iterations);
  REQUIRE(res.converged);
  REQUIRE(res.approach.has_value());
  CHECK(*res.approach == delta);
  // The pixelated face and the 1/sqrt(a - r) edge singularity give an O(dx/a) load error
  // (measured -0.28% and -0.16% at n = 64, 128, i.e. 0.04-0.05 dx/a). Tolerance 0.25 dx/a.
  const double w_ref = flat_punch_load(a, delta, kModulus);
  CHECK(std::abs(res.load / w_ref - 1) <= 0.25 * dx / a);
  // The whole face is in contact, and nothing where the indenter stays clear of the flat surface
  // (h >= delta; there g = h + u - delta > 0 since u > 0).
  const Mask contact = res.pressure > 0;
  CHECK((h == 0.0).select(contact, true).all());
  CHECK((h >= delta).select(!contact, true).all());
}

TEST_CASE("Flat punch under load control: a flat face over a third of the cells",
          "[contact][punch]") {
  // The face (h = 0) holds pi/9 = 35 % of the cells, more than the quarter under which the
  // load-controlled start sets its trial level: the start must still carry the load (not a
  // zero profile). Its approach is the delta of W = 2 a E* delta, to the O(dx/a) of the test
  // above.
  const std::ptrdiff_t n = 96;
  const double a = 1e-3, delta = 1e-6;
  const Grid grid(n, n, 3 * a, 3 * a);
  const Field h = height(grid, FlatPunch{a, 0.01 * grid.dx() * grid.dx() / delta});
  DcfftOperator op(love_kernel(grid, kModulus));
  ContactOptions opts;
  opts.compute_approach = true;
  const ContactResult res =
      ContactSolver(op, opts).solve_load(h, flat_punch_load(a, delta, kModulus));
  INFO("iterations = " << res.iterations);
  REQUIRE(res.converged);
  CHECK(res.pressure.allFinite());
  CHECK(std::abs(*res.approach / delta - 1) <= 0.25 * grid.dx() / a);
  CHECK((h == 0.0).select(res.pressure > 0, true).all());
}

TEST_CASE("Approach control and load control give the same solution", "[contact]") {
  const HertzProblem hp(64);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.compute_approach = true;
  opts.preconditioned = GENERATE(true, false);
  INFO("preconditioned = " << opts.preconditioned);
  ContactSolver solver(op, opts);
  const ContactResult by_load = solver.solve_load(hp.h, kLoad);
  REQUIRE(by_load.converged);
  const ContactResult by_approach = solver.solve_approach(hp.h, *by_load.approach);
  REQUIRE(by_approach.converged);
  // Both stop at a relative pressure change of 1e-10; the remaining errors are a small multiple of
  // that (measured 4e-12 / 7e-12 in the load, 1e-9 / 2.5e-10 in max-norm pressure, classic /
  // preconditioned). 1e-8 is the solver-consistency tier.
  CHECK(std::abs(by_approach.load / kLoad - 1) <= 1e-8);
  CHECK(rel_linf(by_approach.pressure, by_load.pressure) <= 1e-8);
  CHECK(by_approach.contact_area == by_load.contact_area);
  // And the approach-controlled solve meets Hertz's W(delta) = (4/3) E* sqrt(R) delta^(3/2) to the
  // discretisation tier (0.5 (dx/a)^2, times 3/2 for the power of delta): 2.9e-3 (measured 3.4e-4).
  const double w_hertz = hertz_sphere_for_approach(*by_load.approach, kRadius, kModulus).load;
  CHECK(std::abs(by_approach.load / w_hertz - 1) <= 1.5 * 0.5 * std::pow(4.0 / 64.0, 2));
}

TEST_CASE("Load control does not depend on g(0); the approach shifts by c W", "[contact][g0]") {
  const HertzProblem hp(64);
  DcfftOperator exact(love_kernel(hp.grid, kModulus));
  // Two solves agree only to their stopping tolerance: different rounding sends the CG iterates
  // along slightly different paths. The classic iteration amplifies it to the tolerance (measured
  // pressure differences 3e-11, 6e-11, 3e-13 at tolerances 1e-8, 1e-10, 1e-12), so it is compared
  // at 1e-12, near its rounding floor; the preconditioned one needs fewer iterations and stays at
  // 5e-14 already at the default 1e-10.
  ContactOptions opts;
  opts.preconditioned = GENERATE(true, false);
  opts.tolerance = opts.preconditioned ? 1e-10 : 1e-12;
  opts.compute_approach = true;
  const ContactResult ref = ContactSolver(exact, opts).solve_load(hp.h, kLoad);
  REQUIRE(ref.converged);
  // c W = +-delta: a g(0) error as large as the whole approach, and one that would make it
  // negative.
  const double c = GENERATE(1.0, -1.0) * hp.reference.approach / kLoad;
  OffsetOperator shifted(exact, c);
  const ContactResult res = ContactSolver(shifted, opts).solve_load(hp.h, kLoad);
  INFO("preconditioned = " << opts.preconditioned
                           << ", c W / delta = " << c * kLoad / hp.reference.approach);
  REQUIRE(res.converged);
  // In exact arithmetic the iterates are identical (the constant is removed with the mean over the
  // contact set, of both g and K t); what remains is rounding (measured 3.4e-13 and 5e-14 on one
  // machine; the classic iteration, which amplifies rounding to its tolerance of 1e-12, 2.9e-12
  // on another whose FFTW takes other codelets): a few times the tolerance.
  CHECK(rel_linf(res.pressure, ref.pressure) <= (opts.preconditioned ? 2e-12 : 5e-12));
  CHECK(res.contact_area == ref.contact_area);
  CHECK(rel_linf(res.gap, ref.gap) <= 1e-10);
  // The approach carries the error: delta -> delta + c W (measured to 2e-14 relative to c W).
  CHECK(*res.approach - *ref.approach == Approx(c * kLoad).epsilon(1e-11));
  // Without compute_approach none is reported under load control.
  opts.compute_approach = false;
  CHECK_FALSE(ContactSolver(shifted, opts).solve_load(hp.h, kLoad).approach.has_value());
}

TEST_CASE("Coated body on the FRF-spectral operator: g(0) moves only the approach",
          "[contact][g0]") {
  // The real case behind the wrapper test above: a stiff coating (E1/E2 = 5, h = a/2) on the
  // spectral operator, whose g(0) is computed, then perturbed by +50 % (a gross quadrature error).
  const HertzProblem hp(48);
  const Material coating(5 * 210e9, 0.25);
  const Material substrate(210e9, 0.3);
  const LayerStack stack({Coating{coating, 0.5 * hp.reference.contact_radius}}, substrate);
  const auto frf = make_frf(stack);
  FrfSpectralOperator accurate(hp.grid, *frf, 2.0, G0Method::regularized);
  G0Result wrong = accurate.g0();
  wrong.value *= 1.5;
  FrfSpectralOperator perturbed(hp.grid, *frf, 2.0, wrong);
  ContactOptions opts;
  opts.compute_approach = true;
  opts.preconditioned = GENERATE(true, false);
  opts.tolerance = opts.preconditioned ? 1e-10 : 1e-12;  // as in the test above
  INFO("preconditioned = " << opts.preconditioned);
  const ContactResult a = ContactSolver(accurate, opts).solve_load(hp.h, kLoad);
  const ContactResult b = ContactSolver(perturbed, opts).solve_load(hp.h, kLoad);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  // Measured 2.7e-14 (preconditioned, 30 iterations) and 7.4e-13 (classic, 38).
  CHECK(rel_linf(b.pressure, a.pressure) <= 2e-12);
  CHECK(b.contact_area == a.contact_area);
  // The uniform displacement of the k = 0 mode is g(0) * (total force) / (extended area), so the
  // approach moves by 0.5 g(0) W / (alpha^2 lx ly), 9 % of delta here (measured to 6e-14).
  const double shift = 0.5 * accurate.g0().value * kLoad / (4.0 * hp.grid.lx() * hp.grid.ly());
  CHECK(*b.approach - *a.approach == Approx(shift).epsilon(1e-9));
}

TEST_CASE("Preconditioned and classic iterations reach the same solution", "[contact]") {
  const HertzProblem hp(128);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions classic_opts;
  classic_opts.preconditioned = false;
  const ContactResult classic = ContactSolver(op, classic_opts).solve_load(hp.h, kLoad);
  const ContactResult fast = ContactSolver(op).solve_load(hp.h, kLoad);
  REQUIRE(classic.converged);
  REQUIRE(fast.converged);
  // Two different algorithms for one discrete problem: equal to the solver tier.
  CHECK(rel_linf(fast.pressure, classic.pressure) <= 1e-8);
  CHECK(fast.contact_area == classic.contact_area);
  // The |k| preconditioner makes the count nearly N-independent: measured 26 against 53 classic
  // iterations here (and 28-33 from 64^2 to 1024^2). 40 flags a preconditioner that stopped
  // working without tying the test to rounding-level details.
  CHECK(fast.iterations <= 40);
  CHECK(fast.iterations < classic.iterations);
}

namespace {

// Counts the applications of the operator it wraps: the reference for the solver's own count.
class CountingOperator final : public SurfaceOperator {
 public:
  explicit CountingOperator(SurfaceOperator& inner) : inner_(inner) {}
  const Grid& grid() const override { return inner_.grid(); }
  void apply(const Field& p, Field& u) override {
    inner_.apply(p, u);
    ++count;
  }
  coatfft::Method method() const override { return inner_.method(); }
  using SurfaceOperator::apply;
  int count = 0;

 private:
  SurfaceOperator& inner_;
};

}  // namespace

TEST_CASE("One application per iteration: the original's solution at half the cost", "[contact]") {
  const HertzProblem hp(256);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  const ContactControl control = GENERATE(ContactControl::load, ContactControl::approach);
  const double value = control == ContactControl::load ? kLoad : hp.reference.approach;
  ContactOptions original_opts;
  original_opts.update_by_linearity = false;
  CountingOperator counted_original(op);
  const ContactResult original =
      ContactSolver(counted_original, original_opts).solve(hp.h, control, value);
  CountingOperator counted(op);
  const ContactResult fast = ContactSolver(counted).solve(hp.h, control, value);
  INFO("control " << (control == ContactControl::load ? "load" : "approach") << ": "
                  << fast.iterations << " iterations, " << fast.operator_applications
                  << " applications; the original " << original.iterations << ", "
                  << original.operator_applications);
  REQUIRE(original.converged);
  REQUIRE(fast.converged);
  // The counts the solvers report are the applications they made.
  CHECK(original.operator_applications == counted_original.count);
  CHECK(fast.operator_applications == counted.count);
  // The original: two per iteration, one for the approach's start, and one for the result when
  // the last step projected a cell.
  const int start = control == ContactControl::load ? 0 : 1;
  CHECK(original.operator_applications >= 2 * original.iterations + start);
  CHECK(original.operator_applications <= 2 * original.iterations + start + 1);
  // The same discrete problem to the solver tier (both converged to 1e-10).
  CHECK(rel_linf(fast.pressure, original.pressure) <= 1e-8);
  CHECK(fast.contact_area == original.contact_area);
  // Measured 18-23 applications for Hertz from 512^2 to 2048^2 against 55-76 (bench_contact);
  // here 17 (load) and 18 (approach). 30 flags a start or an update that stopped working.
  CHECK(fast.operator_applications <= 30);
  CHECK(fast.operator_applications < original.operator_applications / 2);
}

TEST_CASE("DC-FFT and direct summation give the same contact", "[contact]") {
  // Non-square, odd x size: catches a transposed axis or an off-by-one in the operator plumbing.
  const Grid grid(15, 12, 3e-4, 2.4e-4);
  const InfluenceKernel kernel = love_kernel(grid, kModulus);
  DcfftOperator fast(kernel);
  DirectOperator direct(kernel);
  const Field h = height(grid, Cylinder{0.01, 1e-4, 0.005});
  ContactOptions opts;
  opts.preconditioned = GENERATE(true, false);
  const ContactResult a = ContactSolver(fast, opts).solve_load(h, 0.5);
  const ContactResult b = ContactSolver(direct, opts).solve_load(h, 0.5);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  // Same discrete operator up to FFT rounding (1e-15 relative): same solution to the solver tier.
  CHECK(rel_linf(a.pressure, b.pressure) <= 1e-8);
  // Symmetric problem: the pressure is even in x and in y to the solver tolerance.
  CHECK(rel_linf(a.pressure, a.pressure.colwise().reverse().eval()) <= 1e-8);
  CHECK(rel_linf(a.pressure, a.pressure.rowwise().reverse().eval()) <= 1e-8);
}

TEST_CASE("Non-convergence is reported, not thrown", "[contact]") {
  const HertzProblem hp(32);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.max_iterations = 2;
  ContactResult res;
  REQUIRE_NOTHROW(res = ContactSolver(op, opts).solve_load(hp.h, kLoad));
  CHECK_FALSE(res.converged);
  CHECK(res.status == ContactStatus::iteration_limit);
  CHECK(res.iterations == 2);
  CHECK(res.residual > opts.tolerance);
  CHECK(std::isfinite(res.residual));
  CHECK_THAT(res.warning, Catch::Contains("not converged"));
  // The returned iterate still satisfies the constraints the iteration enforces at every step.
  CHECK(res.pressure.minCoeff() >= 0.0);
  CHECK(std::abs(res.load / kLoad - 1) <= 1e-12);
}

TEST_CASE("Contact reaching the domain edge is flagged", "[contact][bad_input]") {
  const HertzProblem hp(32);  // domain [-2a, 2a] for W = 10 N
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  // 27 W gives a contact radius 3 a, beyond the domain half-width 2 a.
  const ContactResult res = ContactSolver(op).solve_load(hp.h, 27 * kLoad);
  CHECK(res.touches_boundary);
  CHECK_THAT(res.warning, Catch::Contains("domain edge"));
  // The edge is a property of the iterate, not how the iteration ended: this one converged.
  CHECK(res.status == ContactStatus::converged);
  CHECK(res.converged);
  CHECK(res.warning ==
        "contact reaches the domain edge (pressure > 0 on a border cell): the domain is too small "
        "for this load");
  const ContactResult fine = ContactSolver(op).solve_load(hp.h, kLoad);
  CHECK_FALSE(fine.touches_boundary);
  CHECK(fine.status == ContactStatus::converged);
  CHECK(fine.warning.empty());
}

TEST_CASE("The iteration limit is a status with its message", "[contact]") {
  const HertzProblem hp(16);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.max_iterations = 1;
  for (const ContactControl control : {ContactControl::load, ContactControl::approach}) {
    const double value = control == ContactControl::load ? kLoad : hp.reference.approach;
    const ContactResult res = ContactSolver(op, opts).solve(hp.h, control, value);
    CHECK(res.status == ContactStatus::iteration_limit);
    CHECK_FALSE(res.converged);
    CHECK(res.iterations == 1);
    CHECK_FALSE(res.touches_boundary);
    CHECK(res.warning == detail::concat("not converged after 1 iterations (residual ", res.residual,
                                        ", tolerance ", opts.tolerance, ")"));
    CHECK(res.warning == describe(res, opts.tolerance));
  }
}

namespace {

// u = c p + b: a local compliance c [m/Pa] and a rigid shift b [m] that does not depend on p.
// Not an elastic operator; it drives the solver into each of its breakdowns.
class AffineOperator final : public SurfaceOperator {
 public:
  AffineOperator(const Grid& grid, double c, double b) : grid_(grid), c_(c), b_(b) {}
  const Grid& grid() const override { return grid_; }
  void apply(const Field& p, Field& u) override { u = c_ * p + b_; }
  coatfft::Method method() const override { return coatfft::Method::direct; }  // none of its own
  using SurfaceOperator::apply;

 private:
  Grid grid_;
  double c_;
  double b_;
};

}  // namespace

TEST_CASE("Breakdowns are statuses with their messages", "[contact]") {
  const Grid grid(8, 8, 1e-3, 1e-3);
  const Field h = height(grid, Paraboloid{kRadius});
  SECTION("a rigid body (K = 0) has no curvature along any direction") {
    AffineOperator rigid(grid, 0.0, 0.0);
    const ContactResult res = ContactSolver(rigid).solve_load(h, 1.0);
    CHECK(res.status == ContactStatus::non_positive_curvature);
    CHECK_FALSE(res.converged);
    CHECK(res.iterations == 1);
    // The start is returned: the Hertzian cap on the lowest quarter of the cells, inside.
    CHECK(res.contact_area == Approx(0.25 * grid.lx() * grid.ly()).epsilon(0.1));
    CHECK_FALSE(res.touches_boundary);
    CHECK(res.warning == "non-positive curvature along the search direction (breakdown)");
  }
  SECTION("the same in Polonsky & Keer's original iteration") {
    AffineOperator rigid(grid, 0.0, 0.0);
    ContactOptions opts;
    opts.update_by_linearity = false;
    const ContactResult res = ContactSolver(rigid, opts).solve_load(h, 1.0);
    CHECK(res.status == ContactStatus::non_positive_curvature);
    CHECK(res.iterations == 1);
    // Its start, the load spread over the whole domain, is returned: it covers the border, and
    // the breakdown is reported before the edge.
    CHECK(res.touches_boundary);
    CHECK(res.warning ==
          "non-positive curvature along the search direction (breakdown); contact reaches the "
          "domain edge (pressure > 0 on a border cell): the domain is too small for this load");
  }
  SECTION("a shift far above the gap lifts the surface off the indenter") {
    for (const bool preconditioned : {true, false}) {
      ContactOptions opts;
      opts.preconditioned = preconditioned;
      // The shift b is not linear in p: moving u by linearity would drop it from u - tau K t.
      opts.update_by_linearity = false;
      AffineOperator lifted(grid, 1e-15, 1e-3);
      const ContactResult res = ContactSolver(lifted, opts).solve_approach(h, 2e-6);
      CHECK(res.status == ContactStatus::pressure_vanished);
      CHECK_FALSE(res.converged);
      CHECK(res.iterations == 1);
      CHECK(res.load > 0);  // the last iterate that carried pressure
      CHECK(res.warning == "all pressure vanished (breakdown)");
      CHECK(res.warning == describe(res, opts.tolerance));
    }
  }
}

TEST_CASE("Contact statuses have stable names", "[contact]") {
  CHECK(to_string(ContactStatus::converged) == "converged");
  CHECK(to_string(ContactStatus::iteration_limit) == "iteration_limit");
  CHECK(to_string(ContactStatus::pressure_vanished) == "pressure_vanished");
  CHECK(to_string(ContactStatus::non_positive_curvature) == "non_positive_curvature");
  CHECK(to_string(ContactStatus::coupling_limit) == "coupling_limit");
  const ContactResult unsolved;
  CHECK(unsolved.status == ContactStatus::iteration_limit);
  CHECK_FALSE(unsolved.converged);
}

TEST_CASE("Contact solver refuses bad input with InvalidArgument", "[contact][bad_input]") {
  const HertzProblem hp(16);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactSolver solver(op);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(solver.solve_load(hp.h, 0.0), Catch::Contains("load = 0"));
  CHECK_THROWS_AS(solver.solve_load(hp.h, -1.0), InvalidArgument);
  CHECK_THROWS_AS(solver.solve_load(hp.h, nan), InvalidArgument);
  CHECK_THROWS_AS(solver.solve_approach(hp.h, nan), InvalidArgument);
  // The sphere's lowest point is at h = 0 only up to the cell centres: min h > 0 on an even grid.
  CHECK_THROWS_WITH(solver.solve_approach(hp.h, 0.0), Catch::Contains("min(height)"));
  CHECK_THROWS_WITH(solver.solve_load(Field::Zero(16, 15), kLoad), Catch::Contains("(16, 15)"));
  Field bad = hp.h;
  bad(3, 4) = nan;
  CHECK_THROWS_AS(solver.solve_load(bad, kLoad), InvalidArgument);
  CHECK_THROWS_AS(height(hp.grid, HeightMap{Field::Zero(15, 16)}), InvalidArgument);
  // A sphere smaller than the domain's half-diagonal has no surface over the corners.
  const double half_diagonal = std::sqrt(2.0) * 2 * hp.reference.contact_radius;
  CHECK_THROWS_AS(height(hp.grid, Sphere{0.9 * half_diagonal}), InvalidArgument);
  ContactOptions opts;
  opts.tolerance = 0;
  CHECK_THROWS_AS(ContactSolver(op, opts), InvalidArgument);
  opts.tolerance = 1e-10;
  opts.max_iterations = 0;
  CHECK_THROWS_AS(ContactSolver(op, opts), InvalidArgument);
}

TEST_CASE("One-cell-wide grids solve like any other", "[contact]") {
  // A strip of 1 x 9 (and 9 x 1) cells: exercises the degenerate FFT sizes of the operator and of
  // the preconditioner. Reference: the same solve on direct summation.
  const bool along_x = GENERATE(true, false);
  const Grid grid = along_x ? Grid(9, 1, 9e-5, 1e-5) : Grid(1, 9, 1e-5, 9e-5);
  const InfluenceKernel kernel = love_kernel(grid, kModulus);
  DcfftOperator fast(kernel);
  DirectOperator direct(kernel);
  const Field h = height(grid, Paraboloid{0.01});
  ContactOptions opts;
  opts.preconditioned = GENERATE(true, false);
  INFO("along_x = " << along_x << ", preconditioned = " << opts.preconditioned);
  const ContactResult a = ContactSolver(fast, opts).solve_load(h, 0.01);
  ContactOptions classic;
  classic.preconditioned = false;
  const ContactResult b = ContactSolver(direct, classic).solve_load(h, 0.01);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK(rel_linf(a.pressure, b.pressure) <= 1e-8);
  CHECK(a.pressure.minCoeff() >= 0.0);
}

TEST_CASE("The iteration callback sees every step, with falling residuals", "[contact]") {
  const HertzProblem hp(64);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  std::vector<int> steps;
  std::vector<double> residuals;
  opts.on_iteration = [&](int k, double residual) {
    steps.push_back(k);
    residuals.push_back(residual);
  };
  const ContactResult res = ContactSolver(op, opts).solve_load(hp.h, kLoad);
  REQUIRE(res.converged);
  // One call per iteration, numbered from 1, the last with the residual the result reports.
  REQUIRE(steps.size() == static_cast<std::size_t>(res.iterations));
  for (std::size_t i = 0; i < steps.size(); ++i) CHECK(steps[i] == static_cast<int>(i) + 1);
  CHECK(residuals.back() == res.residual);
  CHECK(residuals.back() < opts.tolerance);
  // The preconditioned iteration on Hertz lowers the residual at every step (measured: 28 steps,
  // each ratio r_k / r_(k-1) between 0.16 and 0.98). The classic one does not (one step of its 40
  // raises it by 6 %), which is why only the default is checked for a strict decrease.
  for (std::size_t i = 1; i < residuals.size(); ++i) {
    INFO("iteration " << steps[i]);
    CHECK(residuals[i] < residuals[i - 1]);
  }
  // Watching changes nothing: the same solve without the callback gives the same pressure.
  const ContactResult unwatched = ContactSolver(op).solve_load(hp.h, kLoad);
  CHECK(unwatched.iterations == res.iterations);
  CHECK((unwatched.pressure == res.pressure).all());
}

TEST_CASE("Loads far outside the physical range solve without overflow or NaN",
          "[contact][bad_input][scaling]") {
  // The problem is homogeneous: heights and load scaled by c give pressure, displacement and gap
  // scaled by c (K is linear). The reference is the Hertz problem at 10 N; at 1e195 N and
  // 1e-290 N the iteration's inner products (p g ~ c^2) would overflow or underflow unscaled.
  HertzProblem problem(32);
  DcfftOperator op(love_kernel(problem.grid, kModulus));
  ContactSolver solver(op);
  const ContactResult reference = solver.solve_load(problem.h, kLoad);
  REQUIRE(reference.converged);
  const double c = GENERATE(1e195, 1e-290);
  const ContactResult r = solver.solve_load(problem.h * c, kLoad * c);
  INFO("c = " << c << ", iterations " << r.iterations);
  REQUIRE(r.converged);
  REQUIRE(r.pressure.allFinite());
  REQUIRE(r.gap.allFinite());
  // The scaled inputs h c and W c carry one rounding each: relative 1e-12 is 4000 ulps.
  CHECK((r.pressure - reference.pressure * c).abs().maxCoeff() <= 1e-12 * r.max_pressure);
  CHECK((r.displacement - reference.displacement * c).abs().maxCoeff() <=
        1e-12 * r.displacement.abs().maxCoeff());
  CHECK(r.load == Approx(kLoad * c).epsilon(1e-12));
  CHECK(r.contact_area == reference.contact_area);
  CHECK(r.max_penetration <= 1e-12 * c * problem.h.maxCoeff());
}

TEST_CASE("Extreme loads on ordinary heights: the asymptotes", "[contact][bad_input][scaling]") {
  // 1e-150 N touches only the highest point: its cells share W equally. 1e150 N flattens the
  // surface (heights of a micrometre are nothing against displacements of 1e142 m): the whole
  // free surface is in contact with the pressure of a flat face, p / W -> that of the unit load on
  // h = 0. Displacements 1e-300 or 1e+300 times the heights are beyond double precision: refused.
  HertzProblem problem(32);
  const double cell = problem.grid.dx() * problem.grid.dy();
  DcfftOperator op(love_kernel(problem.grid, kModulus));
  ContactSolver solver(op);
  const ContactResult tiny = solver.solve_load(problem.h, 1e-150);
  INFO("tiny: " << to_string(tiny.status) << " after " << tiny.iterations << ", residual "
                << tiny.residual << ", area " << tiny.contact_area / cell);
  REQUIRE(tiny.converged);
  // The four centre cells of the even grid share the lowest height.
  const auto lowest = (problem.h == problem.h.minCoeff()).count();
  CHECK(lowest == 4);
  CHECK(tiny.contact_area == lowest * cell);
  CHECK(tiny.max_pressure == Approx(1e-150 / (lowest * cell)).epsilon(1e-12));
  CHECK(tiny.gap.allFinite());
  const ContactResult huge = solver.solve_load(problem.h, 1e150);
  const ContactResult flat = solver.solve_load(Field::Zero(32, 32), 1.0);
  REQUIRE(huge.converged);
  REQUIRE(flat.converged);
  REQUIRE(huge.pressure.allFinite());
  // The heights perturb p / W by about span(h) E* L / W ~ 1e-6 1e11 4e-4 / 1e150: far below
  // rounding, so p / W matches the flat face's to the solver's tolerance.
  CHECK((huge.pressure / 1e150 - flat.pressure).abs().maxCoeff() <= 1e-8 * flat.max_pressure);
  for (const double load : {1e-300, 1e300}) {
    CHECK_THROWS_WITH(solver.solve_load(problem.h, load),
                      Catch::Contains("ContactSolver: load = ") &&
                          Catch::Contains("which double precision cannot solve"));
  }
}

TEST_CASE("Solver timings: the parts are accounted once each, within the total",
          "[contact][timings]") {
  // Bookkeeping, not speed: every part is non-negative, the parts add up to no more than the
  // whole solve, and a solve without a preconditioner spends nothing on one.
  const HertzProblem hp(64);
  DcfftOperator op(love_kernel(hp.grid, kModulus));
  ContactOptions opts;
  opts.preconditioned = GENERATE(true, false);
  const ContactResult res = ContactSolver(op, opts).solve_load(hp.h, kLoad);
  REQUIRE(res.converged);
  const ContactTimings& t = res.timings;
  for (const double part : {t.steps, t.recomputations, t.preconditioner, t.passes, t.start})
    CHECK(part >= 0.0);
  CHECK(t.steps > 0.0);
  CHECK(t.steps + t.recomputations + t.preconditioner + t.passes + t.start <= t.total);
  if (!opts.preconditioned) CHECK(t.preconditioner == 0.0);
}
