// Stresses on planes inside the body (stress_plane_kernel, StressOperator) against independent
// references: Holl's closed form for sigma_zz under a uniformly loaded rectangle on a homogeneous
// half-space (Love 1929), the direct double sum of the coefficients (the padded convolution must
// equal it to rounding, for every component, load and parity), and Johnson's (1985) eq. 3.45 on
// the axis of a Hertz pressure.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "stress/detail/closed_form_screen.hpp"
#include "stress/stress_invariants.hpp"
#include "stress/stress_kernel.hpp"
#include "stress/stress_operator.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

// sigma_zz [per unit pressure] at (x, y, z) under a unit pressure on the dx x dy rectangle centred
// at the origin: the corner function of Holl (Love 1929), summed over the four corners.
double holl_szz(double x, double y, double z, double dx, double dy) {
  const auto corner = [z](double X, double Y) {
    const double r = std::sqrt(X * X + Y * Y + z * z);
    return std::atan(X * Y / (z * r)) + X * Y * z / r * (1 / (X * X + z * z) + 1 / (Y * Y + z * z));
  };
  double s = 0.0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      s += (a == b ? 1 : -1) * corner(x + (a - 0.5) * dx, y + (b - 0.5) * dy);
  return -s / (2.0 * M_PI);
}

double holl_error(const Grid& g, double z, int alpha) {
  StressKernelOptions o;
  o.alpha = alpha;
  const StressPlaneKernel k =
      stress_plane_kernel(g, LayerStack(steel), z, InterfaceSide::below, false, o);
  double err = 0.0;
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i)
      err = std::max(err, std::abs(k.coefficients[s_zz][load_p](i, j) -
                                   holl_szz(i * g.dx(), j * g.dy(), z, g.dx(), g.dy())));
  return err;
}

// K(di, dj) from the stored quarter and the parity of (component, load).
double coefficient(const StressPlaneKernel& k, int c, int l, int di, int dj) {
  const auto odd = stress_frf_odd(c, l);
  double v = k.coefficients[c][l](std::abs(di), std::abs(dj));
  if (di < 0 && odd[0]) v = -v;
  if (dj < 0 && odd[1]) v = -v;
  return v;
}

}  // namespace

TEST_CASE("stress kernel: sigma_zz of a homogeneous half-space equals Holl's rectangle",
          "[stress_operator]") {
  const Grid g(32, 24, 1e-3, 0.9e-3);
  // What is left is the periodic images: sigma_zz of a point force falls like 3 F z^3/(2 pi R^5),
  // and the nearest images sit (alpha - 1) L away; a factor 8 covers the sum over the images.
  const auto image_bound = [&](double z, int alpha) {
    const double r = (alpha - 1) * std::min(g.lx(), g.ly());
    return 8.0 * 3.0 * z * z * z * g.dx() * g.dy() / (2.0 * M_PI * std::pow(r, 5));
  };
  // Shallow to deep planes, z from dx/3 to 3 dx: the alias series and the cut-off at work.
  for (double z : {1e-5, 4e-5, 1e-4}) CHECK(holl_error(g, z, 4) < image_bound(z, 4) + 1e-13);
  // A deep plane (z = L/4): doubling alpha shrinks the images' error like ((alpha - 1) L)^-5.
  const double e4 = holl_error(g, 2.5e-4, 4), e8 = holl_error(g, 2.5e-4, 8);
  CHECK(e4 < image_bound(2.5e-4, 4));
  CHECK(e8 < image_bound(2.5e-4, 8));
  CHECK(e8 < e4 / 30.0);
}

TEST_CASE("stress operator equals the direct double sum of its coefficients", "[stress_operator]") {
  const Grid g(7, 5, 1e-3, 0.6e-3);
  const LayerStack stack({{tin, 1e-4, Interface::bonded}}, steel);
  const std::vector<double> depths{5e-5, 1e-4, 3e-4};  // in the coating, on the interface, below
  StressOperatorOptions o;
  o.tangential = true;
  o.kernel.alpha = 2;
  const auto op = make_stress_operator(g, stack, depths, o);  // the factory's product
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Field, 3> loads;
  for (Field& f : loads) f = Field::NullaryExpr(7, 5, [&] { return u(rng); });
  std::vector<PlaneStress> s;
  op->apply(loads[0], &loads[1], &loads[2], s);
  REQUIRE(s.size() == 3);
  StressKernelOptions ko;
  ko.alpha = 2;
  for (std::size_t p = 0; p < depths.size(); ++p) {
    const StressPlaneKernel k =
        stress_plane_kernel(g, stack, depths[p], InterfaceSide::below, true, ko);
    for (int c = 0; c < 6; ++c)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 7; ++i) {
          double direct = 0.0;
          for (int l = 0; l < 3; ++l)
            for (int jj = 0; jj < 5; ++jj)
              for (int ii = 0; ii < 7; ++ii)
                direct += coefficient(k, c, l, i - ii, j - jj) * loads[l](ii, jj);
          CHECK(s[p][c](i, j) == Approx(direct).margin(1e-13));
        }
  }
}

TEST_CASE("stress operator: Hertz pressure on the axis against Johnson eq. 3.45",
          "[stress_operator]") {
  const double a = 1e-3, p0 = 1.0, nu = steel.poisson_ratio();
  const Grid g(129, 129, 4 * a, 4 * a);
  const std::vector<double> depths{0.25 * a, 0.5 * a, a};
  StressOperatorOptions o;
  o.kernel.alpha = 8;
  StressOperator op(g, LayerStack(steel), depths, o);
  std::vector<PlaneStress> s;
  op.apply(hertz_pressure(g, p0, a, Sampling::cell_average), nullptr, nullptr, s);
  const int c = g.centre_i();
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double z = depths[k] / a;
    const double szz = -p0 / (1 + z * z);
    const double srr = -p0 * ((1 + nu) * (1 - z * std::atan(1 / z)) - 0.5 / (1 + z * z));
    // sigma_zz: the load's discretisation error, O(dx^2) (2e-4 at 129^2, 4.6e-5 at 257^2);
    // sigma_xx: also the periodic images at alpha = 8 (1.5e-4 at z = a, docs/stress.md).
    CHECK(std::abs(s[k][s_zz](c, c) - szz) < 3e-4);
    CHECK(std::abs(s[k][s_xx](c, c) - srr) < 4e-4);
    CHECK(std::abs(s[k][s_yy](c, c) - srr) < 4e-4);
    CHECK(std::abs(s[k][s_xz](c, c)) < 1e-14);
  }
}

TEST_CASE("stress operator refuses bad input", "[stress_operator]") {
  const Grid g(8, 8, 1e-3, 1e-3);
  const LayerStack sliding({{tin, 1e-4, Interface::frictionless}}, steel);
  StressOperatorOptions tangential;
  tangential.tangential = true;
  CHECK_THROWS_AS(make_stress_operator(g, sliding, {1e-4}, tangential), InvalidArgument);
  CHECK_THROWS_AS(make_stress_operator(g, LayerStack(steel), {}, {}), InvalidArgument);
  CHECK_THROWS_AS(make_stress_operator(g, LayerStack(steel), {-1e-4}, {}), InvalidArgument);
  // z = 0 (the alias series does not decay) and a plane too shallow for the budget: the quarter
  // disk |k| < k_cut = c/z, c = ln(1e12) + 2 ln(1 + ln(1e12)) + 3, over the lattice cell
  // (pi/L)^2: c^2/(4 pi) (L/z)^2 = 1.11e10 at L/z = 1e4 (plus the band, 3e5).
  CHECK_THROWS_AS(make_stress_operator(g, LayerStack(steel), {0.0}, {}), InvalidArgument);
  CHECK_THROWS_AS(make_stress_operator(g, LayerStack(steel), {1e-7}, {}), InvalidArgument);
  const double z[1] = {1e-7};
  const double c = std::log(1e12) + 2 * std::log1p(std::log(1e12)) + 3;
  CHECK(stress_kernel_evaluations(g, z) == Approx(c * c / (4 * M_PI) * 1e8).epsilon(1e-4));
  StressOperatorOptions bad_alpha;
  bad_alpha.kernel.alpha = 1;
  CHECK_THROWS_AS(make_stress_operator(g, LayerStack(steel), {1e-4}, bad_alpha), InvalidArgument);
  StressOperator op(g, LayerStack(steel), {1e-4}, {});
  std::vector<PlaneStress> s;
  Field p = Field::Zero(8, 8);
  CHECK_THROWS_AS(op.apply(p, &p, nullptr, s), InvalidArgument);
  p(2, 3) = NAN;
  CHECK_THROWS_AS(op.apply(p, nullptr, nullptr, s), InvalidArgument);
  CHECK_THROWS_AS(op.apply(Field::Zero(8, 7), nullptr, nullptr, s), InvalidArgument);
}

TEST_CASE("stress invariants against hand-computed states", "[stress_operator]") {
  // Uniaxial tension: von Mises = Tresca * 2 = s.
  CHECK(von_mises({5.0, 0, 0, 0, 0, 0}) == Approx(5.0).epsilon(1e-15));
  CHECK(tresca({5.0, 0, 0, 0, 0, 0}) == Approx(2.5).epsilon(1e-15));
  // Pure shear tau in xy: principal (tau, 0, -tau), von Mises sqrt(3) tau.
  const auto p = principal_stresses({0, 0, 0, 0, 0, 2.0});
  CHECK(p[0] == Approx(2.0).epsilon(1e-14));
  CHECK(p[1] == Approx(0.0).margin(1e-14));
  CHECK(p[2] == Approx(-2.0).epsilon(1e-14));
  CHECK(von_mises({0, 0, 0, 0, 0, 2.0}) == Approx(2.0 * std::sqrt(3.0)).epsilon(1e-15));
  // Hydrostatic: no shear at all. A rotated state: invariants do not depend on the frame
  // (the xz shear 3 on diag(1, 0, -1) rotated to principal axes by hand).
  CHECK(von_mises({-4, -4, -4, 0, 0, 0}) == Approx(0.0).margin(1e-15));
  const auto q = principal_stresses({1, 0, -1, 0, 3, 0});
  CHECK(q[0] == Approx(std::sqrt(10.0)).epsilon(1e-14));
  CHECK(q[2] == Approx(-std::sqrt(10.0)).epsilon(1e-14));
  CHECK(tresca({1, 0, -1, 0, 3, 0}) == Approx(std::sqrt(10.0)).epsilon(1e-14));
}

TEST_CASE("the closed-form principal stresses against the iterative ones", "[stress_operator]") {
  // Random states: within 1e-12 of the largest component (measured about 2e-14). A double root
  // (uniaxial tension plus hydrostatic pressure), where the closed form loses most: within
  // 1e-7 (about sqrt(eps)); the hand-computed states exactly as above.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> d(-1e9, 1e9);
  for (int n = 0; n < 10000; ++n) {
    StressVector s;
    double largest = 0;
    for (double& c : s) largest = std::max(largest, std::abs(c = d(rng)));
    const auto exact = principal_stresses(s), closed = closed_form_principal_stresses(s);
    for (int k = 0; k < 3; ++k) REQUIRE(std::abs(closed[k] - exact[k]) <= 1e-12 * largest);
  }
  const StressVector doubled{3e8, -1e8, -1e8, 0, 0, 0};
  const auto closed = closed_form_principal_stresses(doubled);
  CHECK(closed[0] == Approx(3e8).epsilon(1e-7));
  CHECK(closed[1] == Approx(-1e8).epsilon(1e-7));
  CHECK(closed[2] == Approx(-1e8).epsilon(1e-7));
  const auto q = closed_form_principal_stresses({1, 0, -1, 0, 3, 0});
  CHECK(q[0] == Approx(std::sqrt(10.0)).epsilon(1e-14));
  CHECK(q[2] == Approx(-std::sqrt(10.0)).epsilon(1e-14));
}

namespace {

// Cell k of the six component arrays c: diag(d) turned by a random rotation (a random unit
// quaternion's matrix R, then R diag(d) R^T).
void set_rotated(std::array<std::vector<double>, 6>& c, std::size_t k, std::array<double, 3> d,
                 std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  w /= norm, x /= norm, y /= norm, z /= norm;
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  const auto m = [&](int i, int j) {
    return r[i][0] * d[0] * r[j][0] + r[i][1] * d[1] * r[j][1] + r[i][2] * d[2] * r[j][2];
  };
  const std::array<double, 6> t{m(0, 0), m(1, 1), m(2, 2), m(1, 2), m(0, 2), m(0, 1)};
  for (int q = 0; q < 6; ++q) c[q][k] = t[q];
}

}  // namespace

TEST_CASE("the closed forms' screening finds the iterative solver's maxima over every cell",
          "[stress_operator]") {
  // Planes of 700 cells (two blocks and a part) with a smooth peak, noise, a plateau of equal
  // largest values, double roots and cells beyond [1e-90, 1e90] Pa: the candidates' iterative
  // maxima, value and first cell, are those of principal_stresses over every cell; von Mises'
  // stress of every cell is von_mises' value exactly.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> noise(-1, 1);
  const std::size_t n = 700;
  for (int plane = 0; plane < 40; ++plane) {
    std::array<std::vector<double>, 6> c;
    for (std::size_t k = 0; k < n; ++k) {
      const double bump = std::exp(-std::pow((double(k) - 300.0 - 5 * plane) / 80.0, 2));
      for (int q = 0; q < 6; ++q) c[q].push_back(1e8 * (bump * (q + 1) + 0.3 * noise(rng)));
    }
    if (plane % 4 == 0) {  // rotated copies of two states with double roots, the largest of all:
      // their closed-form values err by about 1e-8, their iterative ones by 1e-16, so the
      // screening must keep every copy within its error bound for the iterative solver to choose
      for (std::size_t k = 200; k < 215; ++k) set_rotated(c, k, {5e9, -1e8, -1e8}, rng);
      for (std::size_t k = 400; k < 415; ++k) set_rotated(c, k, {6e9, 6e9, 5.9e9}, rng);
    }
    if (plane % 4 == 1)  // a plateau: equal tensors at cells 100..120, the largest of all
      for (std::size_t k = 100; k < 120; ++k)
        for (int q = 0; q < 6; ++q) c[q][k] = 1e9 * (q < 3 ? 3 - q : 0.1);
    if (plane % 4 == 2)  // uniaxial states plus pressure: double roots, the largest among them
      for (std::size_t k = 0; k < n; k += 7) {
        c[0][k] = 5e8 + 1e5 * double(k);
        c[1][k] = c[2][k] = -1e8;
        c[3][k] = c[4][k] = c[5][k] = 0;
      }
    if (plane % 4 == 3) {  // far beyond the closed forms' range, both ways
      for (int q = 0; q < 6; ++q) c[q][650] *= 1e95;
      for (int q = 0; q < 6; ++q) c[q][10] *= 1e-105;
    }
    std::vector<double> mises(n);
    const detail::ClosedFormScreen screen = detail::screen_cells(
        {c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data(), c[5].data()}, n,
        mises.data());
    double tensile = -INFINITY, tresca = -INFINITY, vm = -INFINITY;
    std::size_t at_tensile = 0, at_tresca = 0, at_vm = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const StressVector t{c[0][k], c[1][k], c[2][k], c[3][k], c[4][k], c[5][k]};
      const auto p = principal_stresses(t);
      if (p[0] > tensile) tensile = p[0], at_tensile = k;
      if (0.5 * (p[0] - p[2]) > tresca) tresca = 0.5 * (p[0] - p[2]), at_tresca = k;
      if (von_mises(t) > vm) vm = von_mises(t), at_vm = k;
      REQUIRE(mises[k] == von_mises(t));
    }
    double screened_tensile = -INFINITY, screened_tresca = -INFINITY;
    std::size_t screened_at_tensile = 0, screened_at_tresca = 0;
    for (const std::size_t k : screen.candidates) {
      const auto p = principal_stresses({c[0][k], c[1][k], c[2][k], c[3][k], c[4][k], c[5][k]});
      if (p[0] > screened_tensile) screened_tensile = p[0], screened_at_tensile = k;
      if (0.5 * (p[0] - p[2]) > screened_tresca)
        screened_tresca = 0.5 * (p[0] - p[2]), screened_at_tresca = k;
    }
    INFO("plane " << plane << ": " << screen.candidates.size() << " candidates");
    CHECK(screen.finite);
    CHECK(screen.mises == vm);
    CHECK(screen.mises_cell == at_vm);
    CHECK(screened_tensile == tensile);
    CHECK(screened_at_tensile == at_tensile);
    CHECK(screened_tresca == tresca);
    CHECK(screened_at_tresca == at_tresca);
    // The screening is worth its name: a handful of cells, not the plane.
    CHECK(screen.candidates.size() < n / 10);
  }
  // A value that is not finite anywhere is reported.
  for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL})
    for (const std::size_t k : {std::size_t(0), std::size_t(257), n - 1}) {
      std::array<std::vector<double>, 6> c;
      for (auto& v : c) v.assign(n, 1e6);
      c[k % 6][k] = bad;
      CHECK_FALSE(detail::screen_cells({c[0].data(), c[1].data(), c[2].data(), c[3].data(),
                                        c[4].data(), c[5].data()},
                                       n, nullptr)
                      .finite);
    }
}

TEST_CASE("stress operator: interface conditions and a coating of the substrate's own material",
          "[stress_operator]") {
  const Grid g(24, 20, 3e-3, 2.5e-3);
  const Field p = hertz_pressure(g, 1.0, 1e-3, Sampling::cell_average);
  const Field qx = 0.3 * p;
  const double h = 2e-4;
  StressOperatorOptions o;
  o.kernel.alpha = 4;
  o.tangential = true;
  std::vector<PlaneStress> above, below;
  // Bonded: the tractions on the interface (sigma_zz, sigma_xz, sigma_yz) are continuous; the
  // in-plane stresses jump with the moduli. Rounding: 1e-13 of p0.
  const LayerStack bonded({{tin, h, Interface::bonded}}, steel);
  o.side = InterfaceSide::above;
  StressOperator(g, bonded, {h}, o).apply(p, &qx, nullptr, above);
  o.side = InterfaceSide::below;
  StressOperator(g, bonded, {h}, o).apply(p, &qx, nullptr, below);
  for (int c : {s_zz, s_xz, s_yz}) CHECK((above[0][c] - below[0][c]).abs().maxCoeff() < 1e-13);
  CHECK((above[0][s_xx] - below[0][s_xx]).abs().maxCoeff() > 1e-2);
  // Frictionless, under the pressure alone: no shear on either face.
  const LayerStack sliding({{tin, h, Interface::frictionless}}, steel);
  StressOperatorOptions n;
  n.kernel.alpha = 4;
  for (InterfaceSide side : {InterfaceSide::above, InterfaceSide::below}) {
    n.side = side;
    std::vector<PlaneStress> s;
    StressOperator(g, sliding, {h}, n).apply(p, nullptr, nullptr, s);
    CHECK(s[0][s_xz].abs().maxCoeff() < 1e-13);
    CHECK(s[0][s_yz].abs().maxCoeff() < 1e-13);
    CHECK(s[0][s_zz].abs().maxCoeff() > 0.1);
  }
  // A coating of the substrate's own material is the half-space, to rounding.
  std::vector<PlaneStress> same, half;
  StressOperator(g, LayerStack({{steel, h, Interface::bonded}}, steel), {0.5 * h, 3 * h}, o)
      .apply(p, &qx, nullptr, same);
  StressOperator(g, LayerStack(steel), {0.5 * h, 3 * h}, o).apply(p, &qx, nullptr, half);
  for (int d = 0; d < 2; ++d)
    for (int c = 0; c < 6; ++c) CHECK((same[d][c] - half[d][c]).abs().maxCoeff() < 1e-13);
}

TEST_CASE("stress operator: planes on different sides in one operator are those of one side each",
          "[stress_operator]") {
  // Bitwise: a plane's kernel does not depend on the planes it is grouped with. Ten planes make
  // groups cut both by a change of side and by the group size (8).
  const Grid g(12, 10, 3e-3, 2.5e-3);
  const Field p = hertz_pressure(g, 1.0, 1e-3, Sampling::cell_average);
  const double h = 2e-4;
  const LayerStack bonded({{tin, h, Interface::bonded}}, steel);
  std::vector<double> depths{h, h};
  std::vector<InterfaceSide> sides{InterfaceSide::above, InterfaceSide::below};
  for (int k = 1; k <= 8; ++k) {
    depths.push_back(k * 1e-4);
    sides.push_back(InterfaceSide::above);
  }
  StressOperatorOptions o;
  o.kernel.alpha = 4;
  o.sides = sides;
  std::vector<PlaneStress> mixed;
  make_stress_operator(g, bonded, depths, o)->apply(p, nullptr, nullptr, mixed);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    StressOperatorOptions one;
    one.kernel.alpha = 4;
    one.side = sides[d];
    std::vector<PlaneStress> single;
    make_stress_operator(g, bonded, {depths[d]}, one)->apply(p, nullptr, nullptr, single);
    for (int c = 0; c < 6; ++c) CHECK((mixed[d][c] - single[0][c]).abs().maxCoeff() == 0.0);
  }
  // The interface from above and from below: sigma_xx jumps with the moduli.
  CHECK((mixed[0][s_xx] - mixed[1][s_xx]).abs().maxCoeff() > 1e-2);
  o.sides.pop_back();
  CHECK_THROWS_AS(make_stress_operator(g, bonded, depths, o), InvalidArgument);
}

TEST_CASE("stress operator: a typed depth equal to a running-sum interface is that interface",
          "[stress_operator][interface]") {
  // 10 um + 20 um = 3.0000000000000004e-5: the typed 30e-6 lies one ulp above the interface, in
  // the soft middle coating, unless it is taken as the interface (LayerStack::locate).
  const Material soft(50e9, 0.3);
  const LayerStack stack({{tin, 10e-6, Interface::bonded}, {soft, 20e-6, Interface::bonded}},
                         steel);
  const double exact = stack.interface_depths()[1];
  REQUIRE(exact != 30e-6);
  const Grid g(24, 20, 0.3e-3, 0.25e-3);
  const Field p = hertz_pressure(g, 1e9, 0.1e-3, Sampling::cell_average);
  StressOperatorOptions o;
  o.kernel.alpha = 4;
  std::array<std::vector<PlaneStress>, 2> s;  // above, below: planes {30e-6, exact}
  for (const InterfaceSide side : {InterfaceSide::above, InterfaceSide::below}) {
    o.side = side;
    StressOperator(g, stack, {30e-6, exact}, o).apply(p, nullptr, nullptr, s[int(side)]);
  }
  for (const auto& planes : s)
    for (int c = 0; c < 6; ++c) {
      // The typed depth gives the interface's values on the side asked: the fields are the
      // interface's bit for bit; the alias series' cut-offs (from the depths) differ by an ulp.
      CHECK((planes[0][c] - planes[1][c]).abs().maxCoeff() < 1e-3);  // Pa, 1e-12 of p0
    }
  // And the sides differ: sigma_xx jumps across the interface, by 6.7e7 Pa (6.7 % of p0) at most.
  CHECK((s[0][0][s_xx] - s[1][0][s_xx]).abs().maxCoeff() > 3e7);
}

TEST_CASE("von Mises is finite wherever its value is representable", "[stress][von_mises]") {
  // A stress state and its von Mises value at 1 Pa, scaled by powers of ten up to 1e300 Pa and
  // down to 1e-300 Pa: the unscaled squares overflowed to inf above ~1e154 Pa and underflowed
  // to 0 below ~1e-154 Pa.
  const StressVector unit{1.0, -0.5, 0.25, 0.3, -0.2, 0.1};
  const double expected_unit = von_mises(unit);
  for (const double scale : {1e300, 1e200, 1e-200, 1e-300}) {
    INFO(scale);
    StressVector s = unit;
    for (double& v : s) v *= scale;
    const double vm = von_mises(s);
    REQUIRE(std::isfinite(vm));
    CHECK(vm == Approx(expected_unit * scale).epsilon(1e-14));
  }
  // Differences of components near the largest double: (xx - yy) alone overflows.
  const double big = 0.8e308;
  const double vm = von_mises({big, -big, 0.0, 0.0, 0.0, 0.0});
  REQUIRE(std::isfinite(vm));
  CHECK(vm == Approx(std::sqrt(3.0) * big).epsilon(1e-14));
  CHECK(von_mises({0, 0, 0, 0, 0, 0}) == 0.0);
  CHECK(std::isnan(von_mises({std::nan(""), 0, 0, 0, 0, 0})));
}
