// The 3-D stress FRFs at depth (stress_frf, docs/theory.md 2.7 table T4) against independent
// references: the entries of T4 as printed (written out here term by term), the surface traction
// conditions, equilibrium and Hooke's law in Fourier space with z-derivatives by finite
// differences of LayerModes, and the homogeneous k -> 0 means.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "frf/layer_modes.hpp"
#include "frf/stress_frf.hpp"
#include "layers/layer_stack.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;
using C = std::complex<double>;

namespace {

constexpr C I{0.0, 1.0};

const Material polymer(2e9, 0.45);

StressFrf frf_at(const LayerStack& s, double kx, double ky, double z,
                 InterfaceSide side = InterfaceSide::below) {
  const double k = std::hypot(kx, ky);
  const double zs[1] = {z};
  return stress_frf(LayerModes(s).at(k, zs, side).front(), kx / k, ky / k);
}

}  // namespace

TEST_CASE("stress_frf equals table T4 entry by entry", "[stress_frf]") {
  const LayerStack stack({{tin, 2e-6, Interface::bonded}}, steel);
  const double cx = 0.6, cy = -0.8, k = 3e5;
  const double zs[1] = {1.3e-6};
  const ModeFields m = LayerModes(stack).at(k, zs).front();
  const StressFrf f = stress_frf(m, cx, cy);
  const double dp = m.sLL_p - m.sTT_p, dq = m.sLL_q - m.sTT_q, w = m.sLT_t;
  // T4 as printed in docs/theory.md 2.7: columns p, q_x, q_y.
  const std::array<std::array<C, 3>, 6> t4{{
      {cx * cx * m.sLL_p + cy * cy * m.sTT_p,
       -I * cx * (cx * cx * m.sLL_q + cy * cy * m.sTT_q - 2 * cy * cy * w),
       -I * cy * (cx * cx * m.sLL_q + cy * cy * m.sTT_q + 2 * cx * cx * w)},
      {cy * cy * m.sLL_p + cx * cx * m.sTT_p,
       -I * cx * (cy * cy * m.sLL_q + cx * cx * m.sTT_q + 2 * cy * cy * w),
       -I * cy * (cy * cy * m.sLL_q + cx * cx * m.sTT_q - 2 * cx * cx * w)},
      {m.szz_p, -I * cx * m.szz_q, -I * cy * m.szz_q},
      {I * cy * m.sLz_p, cx * cy * (m.sLz_q - m.sTz_t), cy * cy * m.sLz_q + cx * cx * m.sTz_t},
      {I * cx * m.sLz_p, cx * cx * m.sLz_q + cy * cy * m.sTz_t, cx * cy * (m.sLz_q - m.sTz_t)},
      {cx * cy * dp, -I * cy * (cx * cx * dq + (cx * cx - cy * cy) * w),
       -I * cx * (cy * cy * dq - (cx * cx - cy * cy) * w)},
  }};
  for (int c = 0; c < 6; ++c)
    for (int l = 0; l < 3; ++l) CHECK(std::abs(f.stress[c][l] - t4[c][l]) < 1e-15);
  // Displacement rows.
  CHECK(std::abs(f.displacement[0][0] - I * cx * m.uL_p) < 1e-15 * std::abs(m.uL_p));
  CHECK(std::abs(f.displacement[1][1] - cx * cy * (m.uL_q - m.uT_t)) < 1e-15 * std::abs(m.uL_q));
  CHECK(std::abs(f.displacement[2][2] + I * cy * m.uz_q) < 1e-15 * std::abs(m.uz_q));
}

TEST_CASE("stress_frf meets the surface traction conditions", "[stress_frf]") {
  const LayerStack stack({{polymer, 1e-6, Interface::bonded}}, steel);
  const StressFrf f = frf_at(stack, 2e5, -7e5, 0.0);
  // sigma_iz(0) = -t_i: -1 for the matching load, 0 otherwise.
  const int rows[3] = {s_zz, s_xz, s_yz};
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l)
      CHECK(std::abs(f.stress[rows[i]][l] - (i == l ? -1.0 : 0.0)) < 1e-14);
}

TEST_CASE("stress_frf satisfies equilibrium and Hooke's law inside each medium", "[stress_frf]") {
  // Inverse transform exp(+i k.x): d/dx -> i kx. z-derivatives by 4th-order central differences.
  const LayerStack stack({{tin, 1e-6, Interface::bonded}, {polymer, 2e-6, Interface::frictionless}},
                         steel);
  const double kx = 4e5, ky = 9e5;
  struct Point {
    double z;
    Material m;
  };
  for (const Point& pt : {Point{0.4e-6, tin}, Point{1.9e-6, polymer}, Point{5e-6, steel}}) {
    const double h = 2e-9;
    const auto d_dz = [&](auto get) {
      return (-get(frf_at(stack, kx, ky, pt.z + 2 * h)) +
              8.0 * get(frf_at(stack, kx, ky, pt.z + h)) -
              8.0 * get(frf_at(stack, kx, ky, pt.z - h)) +
              get(frf_at(stack, kx, ky, pt.z - 2 * h))) /
             (12.0 * h);
    };
    const StressFrf f = frf_at(stack, kx, ky, pt.z);
    const double lambda =
        2 * pt.m.shear_modulus() * pt.m.poisson_ratio() / (1 - 2 * pt.m.poisson_ratio());
    const double mu = pt.m.shear_modulus();
    for (int l = 0; l < 3; ++l) {
      const auto s = [&](int c) { return [c, l](const StressFrf& g) { return g.stress[c][l]; }; };
      const auto u = [&](int d) {
        return [d, l](const StressFrf& g) { return g.displacement[d][l]; };
      };
      const double scale = std::abs(f.stress[s_zz][l]) + std::abs(f.stress[s_xx][l]) +
                           std::abs(f.stress[s_xz][l]) + 1e-3;
      // div sigma = 0, three rows.
      CHECK(std::abs(I * kx * f.stress[s_xx][l] + I * ky * f.stress[s_xy][l] + d_dz(s(s_xz))) <
            1e-6 * scale * std::hypot(kx, ky));
      CHECK(std::abs(I * kx * f.stress[s_xy][l] + I * ky * f.stress[s_yy][l] + d_dz(s(s_yz))) <
            1e-6 * scale * std::hypot(kx, ky));
      CHECK(std::abs(I * kx * f.stress[s_xz][l] + I * ky * f.stress[s_yz][l] + d_dz(s(s_zz))) <
            1e-6 * scale * std::hypot(kx, ky));
      // Hooke: sigma = lambda div u + 2 mu eps.
      const C ux = f.displacement[0][l], uy = f.displacement[1][l];
      const C div = I * kx * ux + I * ky * uy + d_dz(u(2));
      CHECK(std::abs(f.stress[s_xx][l] - (lambda * div + 2 * mu * I * kx * ux)) < 1e-6 * scale);
      CHECK(std::abs(f.stress[s_yy][l] - (lambda * div + 2 * mu * I * ky * uy)) < 1e-6 * scale);
      CHECK(std::abs(f.stress[s_xy][l] - mu * (I * ky * ux + I * kx * uy)) < 1e-6 * scale);
      CHECK(std::abs(f.stress[s_xz][l] - mu * (d_dz(u(0)) + I * kx * f.displacement[2][l])) <
            1e-6 * scale);
    }
  }
}

TEST_CASE("stress_frf_at_zero gives the homogeneous means over directions", "[stress_frf]") {
  const LayerStack half(steel);
  const double zs[1] = {1e-3};
  const StressFrf f = stress_frf_at_zero(LayerModes(half).at(1e-9, zs).front());
  const double nu = steel.poisson_ratio();
  // S_xx -> -(cx^2 + 2 nu cy^2), mean -(1 + 2 nu)/2; S_zz -> -1; T_xz^x -> -1 (docs/theory.md 2.7).
  CHECK(f.stress[s_xx][load_p].real() == Approx(-(1 + 2 * nu) / 2).epsilon(1e-10));
  CHECK(f.stress[s_yy][load_p].real() == Approx(-(1 + 2 * nu) / 2).epsilon(1e-10));
  CHECK(f.stress[s_zz][load_p].real() == Approx(-1.0).epsilon(1e-10));
  CHECK(f.stress[s_xz][load_qx].real() == Approx(-1.0).epsilon(1e-10));
  CHECK(f.stress[s_yz][load_qy].real() == Approx(-1.0).epsilon(1e-10));
  CHECK(std::abs(f.stress[s_xy][load_p]) < 1e-15);
  CHECK(std::abs(f.stress[s_xz][load_p]) < 1e-15);
  CHECK(std::abs(f.stress[s_xx][load_qx]) < 1e-15);
}

TEST_CASE("stress_frf_odd follows the parity of T4", "[stress_frf]") {
  const LayerStack stack({{tin, 1e-6, Interface::bonded}}, steel);
  for (int c = 0; c < 6; ++c)
    for (int l = 0; l < 3; ++l) {
      const auto odd = stress_frf_odd(c, l);
      const C f = frf_at(stack, 3e5, 5e5, 1e-6).stress[c][l];
      const C fx = frf_at(stack, -3e5, 5e5, 1e-6).stress[c][l];
      const C fy = frf_at(stack, 3e5, -5e5, 1e-6).stress[c][l];
      CHECK(std::abs(fx - (odd[0] ? -f : f)) < 1e-14);
      CHECK(std::abs(fy - (odd[1] ? -f : f)) < 1e-14);
    }
}
