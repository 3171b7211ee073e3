// CerrutiOperator, the 3 x 3 surface response of a homogeneous half-space, against independent
// references: the direct double sum of Love's and Cerruti's coefficients at every signed offset,
// Betti's reciprocity on the grid, and the closed-form displacements of a uniformly pressed and a
// uniformly sheared disk (Johnson 1985, sections 3.4 and 3.6).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "convolution/kernels/cerruti_influence.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

Field random_load(std::ptrdiff_t nx, std::ptrdiff_t ny, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Field::NullaryExpr(nx, ny, [&] { return u(rng); });
}

}  // namespace

TEST_CASE("CerrutiOperator equals the direct double sum of the coefficients",
          "[cerruti_operator]") {
  const Grid g(6, 5, 1e-3, 0.7e-3);
  const Field p = random_load(6, 5, 1), qx = random_load(6, 5, 2), qy = random_load(6, 5, 3);
  CerrutiOperator op(g, steel);
  std::array<Field, 3> u;
  op.apply(p, &qx, &qy, u);
  const double dx = g.dx(), dy = g.dy(), e_star = steel.plane_strain_modulus();
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 6; ++i) {
      double ux = 0, uy = 0, uz = 0, scale = 0;
      for (int jj = 0; jj < 5; ++jj)
        for (int ii = 0; ii < 6; ++ii) {
          const double x = (i - ii) * dx, y = (j - jj) * dy;
          const CerrutiCoefficients a = cerruti_influence(x, y, dx, dy, steel);
          const CerrutiCoefficients b = cerruti_influence(y, x, dy, dx, steel);  // q_y
          // u_x under p by reciprocity: u_z at the load under q_x at the point, zx(-x, -y).
          const CerrutiCoefficients r = cerruti_influence(-x, -y, dx, dy, steel);
          const CerrutiCoefficients rs = cerruti_influence(-y, -x, dy, dx, steel);
          ux += r.zx * p(ii, jj) + a.xx * qx(ii, jj) + b.yx * qy(ii, jj);
          uy += rs.zx * p(ii, jj) + a.yx * qx(ii, jj) + b.xx * qy(ii, jj);
          uz += love_influence(x, y, dx, dy) / e_star * p(ii, jj) + a.zx * qx(ii, jj) +
                b.zx * qy(ii, jj);
          scale = std::max(scale, std::abs(a.xx));
        }
      CHECK(std::abs(u[0](i, j) - ux) < 1e-13 * scale);
      CHECK(std::abs(u[1](i, j) - uy) < 1e-13 * scale);
      CHECK(std::abs(u[2](i, j) - uz) < 1e-13 * scale);
    }
}

TEST_CASE("CerrutiOperator satisfies Betti's reciprocity on the grid", "[cerruti_operator]") {
  // The work of a pressure on the displacements of a traction equals the traction's on those of
  // the pressure: sum p uz(q) = sum q . u(p), to rounding.
  const Grid g(33, 28, 2e-3, 1.5e-3);
  const Field p = random_load(33, 28, 4), qx = random_load(33, 28, 5), qy = random_load(33, 28, 6);
  const Field zero = Field::Zero(33, 28);
  CerrutiOperator op(g, steel);
  std::array<Field, 3> up, uq;
  op.apply(p, nullptr, nullptr, up);
  op.apply(zero, &qx, &qy, uq);
  const double lhs = (p * uq[2]).sum();
  const double rhs = (qx * up[0] + qy * up[1]).sum();
  CHECK(lhs == Approx(rhs).epsilon(1e-12));
  CHECK(std::abs(lhs) > 1e-3 * (p.abs() * uq[2].abs()).sum());  // not a trivial zero
}

TEST_CASE("CerrutiOperator: a uniformly pressed and a uniformly sheared disk",
          "[cerruti_operator]") {
  const double a = 1e-3, nu = steel.poisson_ratio(), mu = steel.shear_modulus();
  const int m = 32;  // cells per radius
  const Grid g(4 * m + 1, 4 * m + 1, (4 * m + 1) * a / m, (4 * m + 1) * a / m);
  const Field disk = uniform_disk_pressure(g, 1.0, a, Sampling::cell_average);
  CerrutiOperator op(g, steel);
  std::array<Field, 3> u;
  op.apply(disk, nullptr, nullptr, u);
  const auto c = g.centre_i();
  // Inside a uniformly pressed disk u_r = -(1 - 2 nu) p r/(4 mu) (Johnson 1985, section 3.4);
  // the staircase of cell averages at the rim perturbs it by O((dx/a)^2) = 1e-3 times a small
  // constant at r <= a/2 (4.0e-6 measured).
  double worst = 0.0;
  for (int i = 0; i <= m / 2; ++i)
    worst = std::max(worst, std::abs(u[0](c + i, c) + (1 - 2 * nu) * g.x(c + i) / (4 * mu)));
  const double scale = (1 - 2 * nu) * a / (4 * mu);
  INFO("u_r inside: worst " << worst / scale << " of (1 - 2 nu) p a/(4 mu)");
  CHECK(worst < 2e-5 * scale);
  CHECK(std::abs(u[1](c, c)) < 1e-16);  // no u_y on the axis y = 0

  // A uniform q_x on the same disk: u_x(0) = (2 - nu) q a/(2 mu) (tests/test_cerruti_influence.cpp
  // derives it), and by symmetry no u_y, u_z at the centre; the rim's staircase: 8.5e-5 measured.
  const Field zero = Field::Zero(g.nx(), g.ny());
  op.apply(zero, &disk, nullptr, u);
  const double centre = (2 - nu) * a / (2 * mu);
  INFO("u_x(0) " << u[0](c, c) / centre);
  CHECK(u[0](c, c) == Approx(centre).epsilon(3e-4));
  CHECK(std::abs(u[1](c, c)) < 1e-12 * centre);
  CHECK(std::abs(u[2](c, c)) < 1e-12 * centre);
}

TEST_CASE("CerrutiOperator refuses bad loads", "[cerruti_operator]") {
  const Grid g(8, 8, 1e-3, 1e-3);
  CerrutiOperator op(g, steel);
  std::array<Field, 3> u;
  Field p = Field::Zero(8, 8);
  CHECK_THROWS_AS(op.apply(Field::Zero(8, 7), nullptr, nullptr, u), InvalidArgument);
  p(1, 1) = INFINITY;
  CHECK_THROWS_AS(op.apply(p, nullptr, nullptr, u), InvalidArgument);
}

TEST_CASE("make_tangential_operator builds the operator a coated body's constructor builds",
          "[cerruti_operator][make_operator]") {
  // The factory adds threads and timing, nothing to the numbers: its displacements equal the
  // constructor's bitwise, on any thread count (the lattice sums do not depend on it). A coating
  // about a cell thick: the lattice's work grows like (L/h)^2 and the property holds at any h.
  const Grid g(9, 7, 1e-3, 0.8e-3);
  const LayerStack body({Coating{tin, 125e-6, Interface::bonded}}, steel);
  const Field p = random_load(9, 7, 4), qx = random_load(9, 7, 5), qy = random_load(9, 7, 6);
  CerrutiOperator direct(g, body, TractionKernelOptions{});
  std::array<Field, 3> expected, u;
  direct.apply(p, &qx, &qy, expected);
  for (int threads : {1, 2}) {
    TangentialOptions options;
    options.threads = threads;
    const BuiltTangentialOperator built = make_tangential_operator(g, body, options);
    built.op->apply(p, &qx, &qy, u);
    for (int d = 0; d < 3; ++d) CHECK((u[d] == expected[d]).all());
    CHECK(built.report.beta == 125e-6);  // the top coating's thickness
    CHECK(built.setup_seconds > 0.0);
  }
  TangentialOptions bad;
  bad.threads = 0;
  CHECK_THROWS_WITH(make_tangential_operator(g, body, bad),
                    Catch::Contains("threads = 0 must be in 1.."));
  const LayerStack sliding({Coating{tin, 50e-6, Interface::frictionless}}, steel);
  CHECK_THROWS_AS(make_tangential_operator(g, sliding), InvalidArgument);
}
