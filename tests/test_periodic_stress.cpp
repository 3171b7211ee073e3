// Stresses at depth under periodic loads (StressOperator with periodic = true) against independent
// references: the plane-strain closed forms of a sinusoidal pressure and a sinusoidal shear on a
// half-space (Johnson 1985, section 2.5, derived from Airy's function); a layered body under single
// oblique Fourier modes of pressure and traction against the depth FRFs of docs/theory.md 2.7
// evaluated at the mode alone; the mean stress under uniform loads (the centre of a uniformly
// loaded disc much wider than the depth); and a Hertz pressure in a large period against the free
// surface's result, the images' share falling like the period^-3.
//
// A cell-wise constant sampling of cos(k x) is the mode k with the amplitude sinc(k dx/2) of the
// cell's transform, plus aliases at k + 2 pi p/dx whose stresses decay like exp(-2 pi p z/dx):
// below 1e-8 of the amplitude at depths of three cells or more, where the references hold to the
// target 1e-6 of the load's amplitude.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <vector>

#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "frf/layer_modes.hpp"
#include "frf/stress_frf.hpp"
#include "loads/hertz_pressure.hpp"
#include "stress/stress_operator.hpp"
#include "tests/test_materials.hpp"
#include "validation/sinusoidal_stress.hpp"

using namespace coatfft;

namespace {

std::vector<PlaneStress> periodic_stress(const Grid& g, const LayerStack& body,
                                         const std::vector<double>& depths, const Field& p,
                                         const Field* qx = nullptr, const Field* qy = nullptr,
                                         std::vector<InterfaceSide> sides = {}) {
  StressOperatorOptions o;
  o.boundary = Boundary::periodic;
  o.tangential = qx || qy;
  o.sides = std::move(sides);
  StressOperator op(g, body, depths, o);
  std::vector<PlaneStress> s;
  op.apply(p, qx, qy, s);
  return s;
}

// A field of cos(kx x + ky y + phase) at the cell centres, times `amplitude`.
Field mode(const Grid& g, double kx, double ky, double amplitude, double phase = 0.0) {
  Field f(g.nx(), g.ny());
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      f(i, j) = amplitude * std::cos(kx * g.x(i) + ky * g.y(j) + phase);
  return f;
}

double max_abs(const Field& f) {
  return f.abs().maxCoeff();
}

}  // namespace

TEST_CASE("periodic stresses: sinusoidal pressure and shear on a half-space, Johnson 2.5",
          "[stress][periodic]") {
  // Two wavelengths over 1 mm, 32 cells: the planes at 3, 5 and 12 cells.
  const Grid g(32, 4, 1e-3, 0.125e-3);
  const double k = 2 * 2 * M_PI / g.lx(), amp = 1.0, nu = steel.poisson_ratio();
  const double s = detail::sinc(0.5 * k * g.dx());  // the cell-wise constant load's mode
  const std::vector<double> depths{3 * g.dx(), 5 * g.dx(), 12 * g.dx()};
  const Field p = mode(g, k, 0, amp), q = mode(g, k, 0, amp);
  const std::vector<PlaneStress> by_p = periodic_stress(g, LayerStack(steel), depths, p);
  const Field zero = Field::Zero(g.nx(), g.ny());
  const std::vector<PlaneStress> by_q =
      periodic_stress(g, LayerStack(steel), depths, zero, &q, nullptr);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    double err = 0.0;
    for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
        const auto by_p_ref = sinusoidal_stress(k, s * amp, 0.0, nu, g.x(i), depths[d]);
        const auto by_q_ref = sinusoidal_stress(k, 0.0, s * amp, nu, g.x(i), depths[d]);
        for (int c = 0; c < 6; ++c)
          err = std::max({err, std::abs(by_p[d][c](i, j) - by_p_ref[c]),
                          std::abs(by_q[d][c](i, j) - by_q_ref[c])});
      }
    INFO("z = " << depths[d] / g.dx() << " cells");
    CHECK(err < 1e-6 * amp);
  }
}

TEST_CASE("periodic stresses: a coated body under oblique single modes equals its depth FRFs",
          "[stress][periodic]") {
  // A TiN coating 4 cells thick on steel; planes in the coating, on the interface from both
  // sides and in the substrate; the mode (2, 1) periods along (x, y), with a phase.
  const Grid g(24, 16, 0.6e-3, 0.4e-3);
  const double h = 4 * g.dx();
  const LayerStack body({{tin, h}}, steel);
  const double kx = 2 * 2 * M_PI / g.lx(), ky = 1 * 2 * M_PI / g.ly(), phase = 0.3;
  const double kn = std::hypot(kx, ky);
  const double cell = detail::sinc(0.5 * kx * g.dx()) * detail::sinc(0.5 * ky * g.dy());
  const std::vector<double> depths{3 * g.dx(), h, h, 7 * g.dx()};
  const std::vector<InterfaceSide> sides{InterfaceSide::below, InterfaceSide::above,
                                         InterfaceSide::below, InterfaceSide::below};
  const std::array<double, 3> amp{1.0, 0.7, -0.4};  // p, q_x, q_y
  const Field p = mode(g, kx, ky, amp[0], phase), qx = mode(g, kx, ky, amp[1], phase),
              qy = mode(g, kx, ky, amp[2], phase);
  const std::vector<PlaneStress> s = periodic_stress(g, body, depths, p, &qx, &qy, sides);
  const LayerModes modes(body);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    const double zd[1] = {depths[d]};
    const StressFrf f = stress_frf(modes.at(kn, zd, sides[d]).front(), kx / kn, ky / kn);
    double err = 0.0;
    for (int c = 0; c < 6; ++c)
      for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
        for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
          const std::complex<double> e =
              std::polar(cell, kx * g.x(i) + ky * g.y(j) + phase);  // the mode's phase factor
          std::complex<double> v = 0.0;
          for (int l = 0; l < 3; ++l) v += amp[l] * f.stress[c][l] * e;
          err = std::max(err, std::abs(s[d][c](i, j) - v.real()));
        }
    INFO("plane " << d << " at z = " << depths[d] / g.dx() << " cells");
    CHECK(err < 1e-6);
  }
}

TEST_CASE("periodic stresses: uniform loads give the mean stress of a wide loaded disc",
          "[stress][periodic]") {
  // Under the centre of a uniform pressure p on a disc of radius R >> z (Johnson 1985, 3.4):
  // sigma_zz = -p, sigma_xx = sigma_yy = -(1 + 2 nu) p/2, in every plane; the same mean state is
  // the k = 0 term of a periodic surface. A coated body: sigma_zz = -p by equilibrium in every
  // layer, the shear stresses zero.
  const Grid g(8, 8, 1e-3, 1e-3);
  const double p = 2.0, nu = steel.poisson_ratio();
  const Field uniform = Field::Constant(g.nx(), g.ny(), p);
  const std::vector<double> depths{0.1e-3, 0.5e-3, 2e-3};
  const std::vector<PlaneStress> half = periodic_stress(g, LayerStack(steel), depths, uniform);
  const std::vector<PlaneStress> coated =
      periodic_stress(g, LayerStack({{tin, 0.3e-3}}, steel), depths, uniform);
  for (std::size_t d = 0; d < depths.size(); ++d) {
    CHECK(max_abs(half[d][s_zz] + p) < 1e-12 * p);
    CHECK(max_abs(half[d][s_xx] + 0.5 * (1 + 2 * nu) * p) < 1e-9 * p);
    CHECK(max_abs(half[d][s_yy] + 0.5 * (1 + 2 * nu) * p) < 1e-9 * p);
    CHECK(max_abs(coated[d][s_zz] + p) < 1e-9 * p);
    for (int c : {s_yz, s_xz, s_xy}) {
      CHECK(max_abs(half[d][c]) < 1e-12 * p);
      CHECK(max_abs(coated[d][c]) < 1e-12 * p);
    }
  }
}

TEST_CASE("periodic stresses: a contact in a large period tends to the free surface's",
          "[stress][periodic]") {
  // The periodic images of a Hertz pressure (load W, mean W/L^2) act at distances >= L; seen from
  // the depth z << L under the contact they are a mean pressure on the plane less a hole about L
  // wide, whose stresses there scale like (W/L^2)(z/L) (the disc's closed form of Johnson 1985,
  // 3.4): the periodic and free results differ by a share of the load falling like L^-3.
  const double a = 0.1e-3;
  const std::vector<double> depths{0.5 * a, a};
  const auto difference = [&](std::ptrdiff_t n) {
    const Grid g(n, n, n * a / 8, n * a / 8);  // 8 cells per radius
    const Field p = hertz_pressure(g, 1.0, a, Sampling::cell_average);
    const std::vector<PlaneStress> periodic = periodic_stress(g, LayerStack(steel), depths, p);
    StressOperatorOptions o;
    o.kernel.alpha = 8;
    StressOperator free(g, LayerStack(steel), depths, o);
    std::vector<PlaneStress> s;
    free.apply(p, nullptr, nullptr, s);
    const std::ptrdiff_t c = g.centre_i();
    double diff = 0.0;
    for (std::size_t d = 0; d < depths.size(); ++d)
      for (int k = 0; k < 6; ++k)
        diff = std::max(diff, std::abs(periodic[d][k](c, c) - s[d][k](c, c)));
    return diff;
  };
  const double d32 = difference(32), d64 = difference(64);  // L = 4 a, 8 a
  INFO("L = 4a: " << d32 << ", L = 8a: " << d64);
  CHECK(d64 < 0.01);  // (W/L^2)(z/L) at L = 8a, z = a: (2 pi/3)/64/8 = 4e-3 of p0
  CHECK(d32 / d64 > 6.0);
  CHECK(d32 / d64 < 10.0);
}

TEST_CASE("periodic stresses refuse what they cannot compute", "[stress][periodic]") {
  StressOperatorOptions o;
  o.boundary = Boundary::periodic;
  CHECK_THROWS_AS(StressOperator(Grid(9, 8, 1e-3, 1e-3), LayerStack(steel), {1e-4}, o),
                  InvalidArgument);
  o.tangential = true;
  const LayerStack sliding({{tin, 1e-4, Interface::frictionless}}, steel);
  CHECK_THROWS_AS(StressOperator(Grid(8, 8, 1e-3, 1e-3), sliding, {2e-4}, o), InvalidArgument);
  o.tangential = false;
  o.kernel.max_evaluations = 1e3;
  CHECK_THROWS_AS(StressOperator(Grid(8, 8, 1e-3, 1e-3), LayerStack(steel), {1e-7}, o),
                  InvalidArgument);
}
