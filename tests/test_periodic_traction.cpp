// The 3 x 3 surface response of a periodic surface (periodic_traction_kernels) against its
// definition: the kernels' discrete transform at a lattice wavevector k is the FRF times the
// cell's transform summed over every alias k + 2 pi (p/dx, q/dy), the sum the Ewald split
// computes in closed form. Along a lattice axis (k_y = 0) the aliases form one alternating series
// (the cell's transform flips sign from one alias to the next), summed here directly to 1e-9 of
// its size; an oblique wavevector's double series converges only like 1/P and is checked to that
// precision. Bodies: a homogeneous half-space (Cerruti's FRFs, frf/traction_response.hpp) and a
// TiN coating two cells thick, whose remainders need the lattice.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "convolution/kernels/periodic_traction_kernels.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "frf/traction_response.hpp"
#include "loads/hertz_pressure.hpp"
#include "tests/test_materials.hpp"
#include "validation/aliased_traction.hpp"

using namespace coatfft;
using std::numbers::pi;

namespace {

using Complex = std::complex<double>;

// The discrete transform sum_d K(d) exp(-i k.d) of a periodic kernel at lattice point (m, n).
Complex transform(const Grid& g, const Field& k, int m, int n) {
  Complex s = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      s += k(i, j) * std::polar(1.0, -2.0 * pi * (double(m * i) / g.nx() + double(n * j) / g.ny()));
  return s;
}

void check_axis_modes(const Grid& g, const LayerStack& body) {
  const TractionKernels k = periodic_traction_kernels(g, body);
  const TractionResponse r(body);
  const Field* fields[6] = {&k.zp, &k.xx, &k.yy, &k.yx, &k.zx, &k.zy};
  const double scale = r.at_infinity().s * g.dx();  // a cell's displacement per unit load
  // Along x (k_y = 0) and along y (k_x = 0): one alternating series each; its partial sums'
  // mean at P and P + 1 errs by about the term's change, (1/P)^3 of it.
  for (auto [m, n] : {std::pair{1, 0}, {3, 0}, {g.nx() / 2 - 1, 0}, {0, 1}, {0, g.ny() / 2 - 1}}) {
    const auto reference = aligned_alias_sum(g, r, m, n, 4000);
    for (int c = 0; c < 6; ++c) {
      INFO("mode (" << m << ", " << n << "), kernel " << c);
      CHECK(std::abs(transform(g, *fields[c], m, n) - reference[c]) < 1e-9 * scale);
    }
  }
  // An oblique wavevector: the double series to |p|, |q| <= 400, whose truncation (it converges
  // like 1/P, the sign flips make it far closer) left 1.4e-8 of a cell's displacement
  // (docs/validation/traction.md).
  const auto a = alias_sum(g, r, 2, 1, 400, 400);
  for (int c = 0; c < 6; ++c) {
    INFO("oblique mode, kernel " << c);
    CHECK(std::abs(transform(g, *fields[c], 2, 1) - a[c]) < 1e-7 * scale);
  }
}

}  // namespace

TEST_CASE("periodic traction kernels of a half-space are their aliased FRFs",
          "[periodic_traction]") {
  check_axis_modes(Grid(16, 12, 1e-3, 0.6e-3), LayerStack(steel));
}

TEST_CASE("periodic traction kernels of a coated body are their aliased FRFs",
          "[periodic_traction]") {
  const Grid g(16, 12, 1e-3, 0.6e-3);
  check_axis_modes(g, LayerStack({{tin, 2 * g.dx()}}, steel));
}

TEST_CASE("periodic traction kernels: parities, zero means, refusals", "[periodic_traction]") {
  const Grid g(12, 10, 1e-3, 0.8e-3);
  const TractionKernels k = periodic_traction_kernels(g, LayerStack({{tin, 1e-4}}, steel));
  for (const Field* f : {&k.zp, &k.xx, &k.yy, &k.yx, &k.zx, &k.zy})
    CHECK(std::abs(f->sum()) < 1e-12 * f->abs().maxCoeff() * f->size());
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
      const std::ptrdiff_t mi = (g.nx() - i) % g.nx(), mj = (g.ny() - j) % g.ny();
      CHECK(k.xx(mi, j) == Approx(k.xx(i, j)).margin(1e-20));
      CHECK(k.zx(mi, j) == Approx(-k.zx(i, j)).margin(1e-20));
      CHECK(k.zy(i, mj) == Approx(-k.zy(i, j)).margin(1e-20));
      CHECK(k.yx(mi, j) == Approx(-k.yx(i, j)).margin(1e-20));
    }
  CHECK_THROWS_AS(periodic_traction_kernels(Grid(11, 10, 1e-3, 1e-3), LayerStack(steel)),
                  InvalidArgument);
  const LayerStack sliding({{tin, 1e-4, Interface::frictionless}}, steel);
  CHECK_THROWS_AS(periodic_traction_kernels(g, sliding), InvalidArgument);
}

TEST_CASE("the periodic tangential operator is the circular convolution of its kernels",
          "[periodic_traction]") {
  // Random loads on a small period: every displacement against the direct double sum over the
  // period of the kernels (offsets modulo the period), to rounding.
  const Grid g(8, 6, 0.4e-3, 0.3e-3);
  const LayerStack body({{tin, 0.05e-3}}, steel);
  TangentialOptions options;
  options.boundary = Boundary::periodic;
  const BuiltTangentialOperator built = make_tangential_operator(g, body, options);
  REQUIRE(built.op->periodic());
  const TractionKernels k = periodic_traction_kernels(g, body);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Field, 3> load;
  for (Field& f : load) f = Field::NullaryExpr(g.nx(), g.ny(), [&] { return u(rng); });
  std::array<Field, 3> out;
  built.op->apply(load[0], &load[1], &load[2], out);
  // kernel[d][l]: u_d under load l (p, q_x, q_y); u_x, u_y under p by reciprocity.
  const Field xp = -k.zx, yp = -k.zy;
  const Field* kernel[3][3] = {{&xp, &k.xx, &k.yx}, {&yp, &k.yx, &k.yy}, {&k.zp, &k.zx, &k.zy}};
  const double scale = k.xx.abs().maxCoeff();
  for (int d = 0; d < 3; ++d)
    for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
        double sum = 0.0;
        for (int l = 0; l < 3; ++l)
          for (std::ptrdiff_t b = 0; b < g.ny(); ++b)
            for (std::ptrdiff_t a = 0; a < g.nx(); ++a)
              sum += (*kernel[d][l])((i - a + g.nx()) % g.nx(), (j - b + g.ny()) % g.ny()) *
                     load[l](a, b);
        CHECK(std::abs(out[d](i, j) - sum) < 1e-13 * scale * 48);
      }
}

TEST_CASE("a traction in a large period tends to the free surface's, but for the images' share",
          "[periodic_traction]") {
  // A Hertz-type traction q_x (radius a, 4 cells per radius) with its pressure on a coated body,
  // periodic in L = 8a and 16a, against the free surface under the same loads less their means
  // over the period: the periodic surface leaves out k = 0, the mean displacement and the
  // uniform strain the mean loads would add (under a mean pressure p_m a free surface strains by
  // -(1 - 2 nu)(1 + nu) p_m/(2E) in the plane, Johnson 1985, 3.4; not periodic). The shapes are
  // compared, u(x) - u(centre) over the contact: the rest of the images, at distances >= L, add
  // a field whose variation over the contact falls like L^-3 (their curvature). Measured: 8.6 to
  // 8.9 per doubling; with the means left in the free loads the coupling terms fall like L^-2.
  const double a = 0.1e-3;
  const LayerStack body({{tin, 0.25 * a}}, steel);
  const auto difference = [&](std::ptrdiff_t n) {
    const Grid g(n, n, n * a / 4, n * a / 4);
    const Field q = hertz_pressure(g, 1.0, a, Sampling::cell_average);
    std::array<Field, 3> free_u, periodic_u;
    TangentialOptions options;
    const Field q_free = q - q.mean();
    make_tangential_operator(g, body, options).op->apply(q_free, &q_free, nullptr, free_u);
    options.boundary = Boundary::periodic;
    make_tangential_operator(g, body, options).op->apply(q, &q, nullptr, periodic_u);
    const std::ptrdiff_t c = g.centre_i();
    double diff = 0.0, scale = 0.0;
    for (int d = 0; d < 3; ++d)
      for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
        for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
          if (std::hypot(g.x(i), g.y(j)) > a) continue;
          const double f = free_u[d](i, j) - free_u[d](c, c);
          const double p = periodic_u[d](i, j) - periodic_u[d](c, c);
          diff = std::max(diff, std::abs(p - f));
          scale = std::max(scale, std::abs(free_u[0](i, j)));
        }
    return diff / scale;
  };
  const double d8 = difference(32), d16 = difference(64);  // L = 8a, 16a
  INFO("L = 8a: " << d8 << ", L = 16a: " << d16);
  CHECK(d16 < 5e-4);
  CHECK(d8 / d16 > 6.0);
  CHECK(d8 / d16 < 10.0);
}
