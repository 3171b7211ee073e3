// The closed-form stresses of a sliding Hertz contact (validation/hertz_stress.hpp) against
// independent references: Johnson's (1985) closed forms on the axis and on the surface, the
// surface boundary conditions, equilibrium by finite differences, Hamilton's (1983) trailing-edge
// stress, and Boussinesq's and Cerruti's point-force fields integrated over the contact.
#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "long_double_gauss_legendre.hpp"
#include "tests/test_support.hpp"
#include "validation/hertz_stress.hpp"

using coatfft::hertz_sliding_stress;
using coatfft::StressTensor;

namespace {

using std::numbers::pi;
using Six = std::array<double, 6>;  // xx, yy, zz, yz, xz, xy

constexpr double kContactRadius = 1e-4;  // contact radius [m]
constexpr double kPeakPressure = 1e9;    // peak pressure p0 [Pa]

Six six(const StressTensor& s) {
  return {s.xx, s.yy, s.zz, s.yz, s.xz, s.xy};
}

// Stresses in units of p0 at (x, y, z) in units of a.
Six stress(double x, double y, double z, double nu, double mu) {
  Six s = six(hertz_sliding_stress(x * kContactRadius, y * kContactRadius, z * kContactRadius,
                                   kPeakPressure, kContactRadius, nu, mu));
  for (double& v : s) v /= kPeakPressure;
  return s;
}

double max_difference(const Six& a, const Six& b) {
  double worst = 0.0;
  for (int c = 0; c < 6; ++c) worst = std::max(worst, std::abs(a[c] - b[c]));
  return worst;
}

// Johnson (1985), eq. 3.45 in units of p0 at depth z/a: {sigma_r = sigma_theta, sigma_z}. At
// z = 0, z atan(1/z) -> 0.
std::array<double, 2> johnson_axis(double nu, double z) {
  const double zt = z > 0 ? z * std::atan(1.0 / z) : 0.0;
  return {-((1 + nu) * (1 - zt) - 0.5 / (1 + z * z)), -1.0 / (1 + z * z)};
}

}  // namespace

TEST_CASE("Hertz stress: the axis against Johnson 3.45", "[hertz_stress]") {
  // Frictionless: sigma_xx = sigma_yy = sigma_r, sigma_zz of eq. 3.45, no shear (symmetry), to
  // 1e-12 p0 (both sides are closed forms; the axis is the r -> 0 limit of the series in r).
  // Measured: 1.6e-14 p0 (at z = 50 a, where terms of order p0 cancel to ~p0 a^2/z^2).
  double worst = 0.0;
  for (double nu : {0.3, 0.5, 0.0, -0.4}) {
    for (double z : {0.0, 1e-9, 1e-4, 0.01, 0.1, 0.3, 0.48, 0.7, 1.0, 1.7, 3.0, 10.0, 50.0}) {
      const auto [sr, sz] = johnson_axis(nu, z);
      const double e = max_difference(stress(0.0, 0.0, z, nu, 0.0), {sr, sr, sz, 0.0, 0.0, 0.0});
      worst = std::max(worst, e);
      INFO("nu = " << nu << ", z/a = " << z);
      CHECK(e <= 1e-12);
    }
  }
  WARN("axis against Johnson 3.45, worst error (of p0): " << worst);
}

namespace {}  // namespace

TEST_CASE("Hertz stress: the largest shear stress on the axis (Johnson 1985)", "[hertz_stress]") {
  // Johnson (1985, section 4.2) quotes the maximum of (sigma_r - sigma_z)/2 on the axis as
  // 0.31 p0 at z = 0.48 a for nu = 0.3: checked to its rounding (0.005 p0, 0.005 a).
  // Measured: 0.310021 p0 at z = 0.480864 a.
  const auto tau = [](double z) {
    const Six s = stress(0.0, 0.0, z, 0.3, 0.0);
    return 0.5 * (s[0] - s[2]);
  };
  const auto [z, tau_max] = maximise(tau, 0.1, 1.5);
  CHECK(std::abs(tau_max - 0.31) <= 0.005);
  CHECK(std::abs(z - 0.48) <= 0.005);
  WARN("largest shear on the axis: " << tau_max << " p0 at z = " << z << " a");
}

TEST_CASE("Hertz stress: the surface boundary conditions", "[hertz_stress]") {
  // At z = 0: sigma_zz = -p, sigma_xz = -mu p, sigma_yz = 0, inside, outside and on the contact
  // edge, to 1e-12 p0 (exact expressions; only rounding). At z = 1e-9 a, away from the edge
  // (|r - a| >= 0.05 a, where the field is smooth), the same to 1e-8 p0: the stresses move by
  // O(z/a) p0 from their surface values. Measured: 3.3e-16 at z = 0, 3.3e-09 at z = 1e-9 a.
  double worst0 = 0.0, worst1 = 0.0;
  for (double nu : {0.3, 0.5}) {
    for (double mu : {0.0, 0.25, -0.4}) {
      for (double x : {-2.0, -1.0, -0.7, -0.3, -0.1, 0.0, 0.05, 0.2, 0.6, 0.9, 1.0, 1.5}) {
        for (double y : {-1.3, -0.8, -0.2, 0.0, 0.15, 0.5, 1.0}) {
          const double r2 = x * x + y * y, p = r2 < 1 ? std::sqrt(1 - r2) : 0.0;
          const Six s0 = stress(x, y, 0.0, nu, mu);
          const double e0 =
              std::max({std::abs(s0[2] + p), std::abs(s0[4] + mu * p), std::abs(s0[3])});
          worst0 = std::max(worst0, e0);
          INFO("nu = " << nu << ", mu = " << mu << ", (x, y)/a = (" << x << ", " << y << ")");
          CHECK(e0 <= 1e-12);
          if (std::abs(std::sqrt(r2) - 1.0) < 0.05) continue;
          const Six s1 = stress(x, y, 1e-9, nu, mu);
          const double e1 =
              std::max({std::abs(s1[2] + p), std::abs(s1[4] + mu * p), std::abs(s1[3])});
          worst1 = std::max(worst1, e1);
          CHECK(e1 <= 1e-8);
        }
      }
    }
  }
  WARN("surface conditions, worst error (of p0): " << worst0 << " at z = 0, " << worst1
                                                   << " at z = 1e-9 a");
}

TEST_CASE("Hertz stress: the frictionless surface stresses against Johnson 3.41-3.42",
          "[hertz_stress]") {
  // Johnson (1985), eqs. 3.41b (r < a) and 3.42 (r >= a), polar components rotated into
  // Cartesian ones at azimuth theta: xx = sr c^2 + st s^2, yy = sr s^2 + st c^2,
  // xy = (sr - st) s c. To 1e-12 p0; r >= 0.1 a keeps the reference's 1 - (1 - r^2)^(3/2) free of
  // cancellation. Measured: 4.4e-16 p0.
  double worst = 0.0;
  for (double nu : {0.3, 0.5, 0.1}) {
    for (double r : {0.1, 0.3, 0.5, 0.8, 0.95, 0.999, 1.0, 1.001, 1.2, 2.0, 5.0}) {
      for (double theta : {0.0, 0.4, 1.3, 2.2, 3.5, 5.0}) {
        // The reference at the radius the function sees, (x a)/a: near r = a a rounding of r
        // moves sqrt(1 - r^2) by 1e-8.
        const double c = std::cos(theta), s = std::sin(theta), x = r * c, y = r * s;
        const double xa = x * kContactRadius / kContactRadius,
                     ya = y * kContactRadius / kContactRadius;
        const double s2 = xa * xa + ya * ya, k = (1 - 2 * nu) / (3 * s2);
        double sr = k, st = -k;
        if (s2 < 1) {
          const double root = std::sqrt(1 - s2);
          sr = k * (1 - root * root * root) - root;
          st = -k * (1 - root * root * root) - 2 * nu * root;
        }
        const Six ref{sr * c * c + st * s * s,
                      sr * s * s + st * c * c,
                      s2 < 1 ? -std::sqrt(1 - s2) : 0.0,
                      0.0,
                      0.0,
                      (sr - st) * s * c};
        const double e = max_difference(stress(x, y, 0.0, nu, 0.0), ref);
        worst = std::max(worst, e);
        INFO("nu = " << nu << ", r/a = " << r << ", theta = " << theta);
        CHECK(e <= 1e-12);
      }
    }
  }
  WARN("surface against Johnson 3.41-3.42, worst error (of p0): " << worst);
}

namespace {

// Divergence of the stress field, (d sigma_ij / d x_j)_i, by fourth-order central differences
// of step h (all in units of a and p0).
template <class Field>
std::array<double, 3> divergence(const Field& f, double x, double y, double z, double h) {
  // Row i of the tensor as components (xx, xy, xz), (xy, yy, yz), (xz, yz, zz) of Six.
  constexpr int row[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
  std::array<double, 3> div{};
  for (int j = 0; j < 3; ++j) {
    const auto at = [&](double d) {
      return f(x + (j == 0 ? d : 0.0), y + (j == 1 ? d : 0.0), z + (j == 2 ? d : 0.0));
    };
    const Six a = at(-2 * h), b = at(-h), c = at(h), d = at(2 * h);
    for (int i = 0; i < 3; ++i) {
      const int k = row[i][j];
      div[i] += (a[k] - 8 * b[k] + 8 * c[k] - d[k]) / (12 * h);
    }
  }
  return div;
}

}  // namespace

TEST_CASE("Hertz stress: equilibrium by finite differences", "[hertz_stress]") {
  // d sigma_ij / d x_j = 0 at points inside, outside and under the edge of the contact, near the
  // surface, on and next to the axis (where the series in r take over) and at depth. Fourth-order
  // differences of step h = 1.25e-4 a: the truncation, ~h^4 |d^5 sigma|, is largest near the
  // edge at z = 0.05 a (it fell by 16 per halving of h there: 6e-11 p0/a at this h), rounding
  // ~1e-12 p0/a; tolerance 1e-9 p0/a. Measured: 6.6e-11 p0/a.
  const std::vector<std::array<double, 3>> points{
      {0.3, 0.2, 0.4}, {-0.7, 0.5, 0.1},   {1.3, -0.4, 0.6},   {0.05, 0.02, 0.3},
      {0.0, 0.0, 0.5}, {0.2795, 0.0, 0.5}, {-1.02, 0.1, 0.05}, {0.9, -0.3, 0.05},
      {2.5, 1.5, 1.0}, {0.1, -0.6, 2.0},   {0.0, 0.3, 0.2}};
  double worst = 0.0;
  for (double nu : {0.3, 0.5}) {
    for (double mu : {0.0, 0.25}) {
      const auto field = [&](double x, double y, double z) { return stress(x, y, z, nu, mu); };
      for (const auto& p : points) {
        const auto div = divergence(field, p[0], p[1], p[2], 1.25e-4);
        const double e = std::max({std::abs(div[0]), std::abs(div[1]), std::abs(div[2])});
        worst = std::max(worst, e);
        INFO("nu = " << nu << ", mu = " << mu << ", (x, y, z)/a = (" << p[0] << ", " << p[1] << ", "
                     << p[2] << ")");
        CHECK(e <= 1e-9);
      }
    }
  }
  WARN("equilibrium, worst residual (of p0/a): " << worst);
}

TEST_CASE("Hertz stress: the tensile stress at the trailing edge (Hamilton 1983)",
          "[hertz_stress]") {
  // Hamilton (1983): under sliding the largest tensile stress is sigma_x at the trailing edge
  // (x, y) = (-a, 0) of the surface, sigma_x = p0 [(1 - 2 nu)/3 + (4 + nu) pi mu / 8]; checked to
  // 1e-12 p0, as the largest sigma_xx on a surface grid, and as the limit of the field from inside
  // the body (at distance d = 1e-10 a the field differs by O(sqrt(d/a)) p0 near the edge: 1e-4).
  // Measured: 0 at the edge, 2.9e-05 p0 approached from inside.
  double worst = 0.0, worst_limit = 0.0;
  for (double nu : {0.3, 0.5, 0.2}) {
    for (double mu : {0.25, 0.1, 0.5}) {
      const double ref = (1 - 2 * nu) / 3 + (4 + nu) * pi * mu / 8;
      const double e = std::abs(stress(-1.0, 0.0, 0.0, nu, mu)[0] - ref);
      const double near = std::abs(stress(-1.0 - 1e-10, 0.0, 1e-10, nu, mu)[0] - ref);
      worst = std::max(worst, e);
      worst_limit = std::max(worst_limit, near);
      INFO("nu = " << nu << ", mu = " << mu);
      CHECK(e <= 1e-12);
      CHECK(near <= 1e-4);
      double largest = -1e300;
      for (int i = -40; i <= 40; ++i)
        for (int j = -40; j <= 40; ++j)
          largest = std::max(largest, stress(0.05 * i, 0.05 * j, 0.0, nu, mu)[0]);
      CHECK(largest <= ref + 1e-12);
    }
  }
  WARN("trailing edge, worst error (of p0): " << worst << " at the edge, " << worst_limit
                                              << " approached from inside");
}

namespace {

// Point forces on the surface of the half-space, stresses per unit force (z into the body,
// tension positive). Boussinesq, unit normal force pressing into the body: Johnson (1985) eqs.
// 3.18-3.20, polar components rotated into Cartesian ones. t = 1/(R (R + z)) = (1 - z/R)/r^2.
Six boussinesq(double x, double y, double z, double nu) {
  const double r2 = x * x + y * y, R = std::sqrt(r2 + z * z), R3 = R * R * R, R5 = R3 * R * R;
  const double t = 1.0 / (R * (R + z)), c = 1.0 / (2 * pi);
  const double srr = c * ((1 - 2 * nu) * t - 3 * z * r2 / R5);
  const double stt = c * (1 - 2 * nu) * (z / R3 - t);
  const double d = (srr - stt) / r2;
  return {stt + d * x * x,         stt + d * y * y,         -3 * c * z * z * z / R5,
          -3 * c * y * z * z / R5, -3 * c * x * z * z / R5, d * x * y};
}

// Cerruti, unit tangential force in +x: Johnson (1985) section 3.3 (Love 1952).
Six cerruti(double x, double y, double z, double nu) {
  const double R = std::sqrt(x * x + y * y + z * z), R2 = R * R, R3 = R2 * R, R5 = R3 * R2;
  const double Rz = R + z, Rz2 = Rz * Rz, Rz3 = Rz2 * Rz, c = 1.0 / (2 * pi), k = 1 - 2 * nu;
  const double x2 = x * x, y2 = y * y;
  const double xx = -3 * x * x2 / R5 + k * (x / R3 - 3 * x / (R * Rz2) + x * x2 / (R3 * Rz2) +
                                            2 * x * x2 / (R2 * Rz3));
  const double yy = -3 * x * y2 / R5 +
                    k * (x / R3 - x / (R * Rz2) + x * y2 / (R3 * Rz2) + 2 * x * y2 / (R2 * Rz3));
  const double xy =
      -3 * x2 * y / R5 + k * (-y / (R * Rz2) + x2 * y / (R3 * Rz2) + 2 * x2 * y / (R2 * Rz3));
  return {c * xx, c * yy, -3 * c * x * z * z / R5, -3 * c * x * y * z / R5, -3 * c * x2 * z / R5,
          c * xy};
}

// Their displacements times the shear modulus (Johnson 1985, eqs. 3.19 and section 3.3).
std::array<double, 3> boussinesq_u(double x, double y, double z, double nu) {
  const double R = std::sqrt(x * x + y * y + z * z), R3 = R * R * R, c = 1.0 / (4 * pi);
  const double w = (1 - 2 * nu) / (R * (R + z));
  return {c * (x * z / R3 - w * x), c * (y * z / R3 - w * y), c * (z * z / R3 + 2 * (1 - nu) / R)};
}
std::array<double, 3> cerruti_u(double x, double y, double z, double nu) {
  const double R = std::sqrt(x * x + y * y + z * z), R3 = R * R * R, Rz = R + z;
  const double c = 1.0 / (4 * pi), k = 1 - 2 * nu;
  return {c * (1 / R + x * x / R3 + k * (1 / Rz - x * x / (R * Rz * Rz))),
          c * (x * y / R3 - k * x * y / (R * Rz * Rz)), c * (x * z / R3 + k * x / (R * Rz))};
}

// Hooke's law (shear modulus 1) of a displacement field, gradients by fourth-order differences.
template <class Displacement>
Six hooke(const Displacement& u, double x, double y, double z, double nu) {
  const double h = 1e-3;
  double g[3][3];  // g[i][j] = d u_i / d x_j
  for (int j = 0; j < 3; ++j) {
    const auto at = [&](double d) {
      return u(x + (j == 0 ? d : 0.0), y + (j == 1 ? d : 0.0), z + (j == 2 ? d : 0.0), nu);
    };
    const auto a = at(-2 * h), b = at(-h), c = at(h), d = at(2 * h);
    for (int i = 0; i < 3; ++i) g[i][j] = (a[i] - 8 * b[i] + 8 * c[i] - d[i]) / (12 * h);
  }
  const double lambda = 2 * nu / (1 - 2 * nu), trace = g[0][0] + g[1][1] + g[2][2];
  return {lambda * trace + 2 * g[0][0],
          lambda * trace + 2 * g[1][1],
          lambda * trace + 2 * g[2][2],
          g[1][2] + g[2][1],
          g[0][2] + g[2][0],
          g[0][1] + g[1][0]};
}

// The point-force fields times p and mu p integrated over the contact, in units of p0 and a:
// r = sin(s), so that p r dr = cos(s)^2 sin(s) ds is smooth at the edge, Gauss-Legendre in s on
// [0, pi/2] (ns nodes) and the trapezoidal rule, spectrally accurate for the periodic integrand,
// in the azimuth (2 ns nodes). For z > 0 the integrand is smooth.
Six point_force_integral(double x, double y, double z, double nu, double mu, int ns) {
  const LongDoubleRule rule = long_double_gauss_legendre(ns);
  const int nphi = 2 * ns;
  Six sum{};
  for (int i = 0; i < ns; ++i) {
    const double s = (static_cast<double>(rule.nodes[i]) + 1) * pi / 4;
    const double w = static_cast<double>(rule.weights[i]) * pi / 4 * std::sin(s) * std::cos(s) *
                     std::cos(s) * 2 * pi / nphi;
    for (int k = 0; k < nphi; ++k) {
      const double phi = 2 * pi * k / nphi;
      const double dx = x - std::sin(s) * std::cos(phi), dy = y - std::sin(s) * std::sin(phi);
      const Six b = boussinesq(dx, dy, z, nu), c = cerruti(dx, dy, z, nu);
      for (int m = 0; m < 6; ++m) sum[m] += w * (b[m] + mu * c[m]);
    }
  }
  return sum;
}

}  // namespace

TEST_CASE("Hertz stress: the point-force fields of the quadrature reference", "[hertz_stress]") {
  // The Boussinesq and Cerruti stresses as written above: Hooke's law of their displacements
  // (fourth-order differences of step 1e-3, error ~1e-12 at these distances), equilibrium, and
  // a traction-free surface away from the force. Measured: Hooke 4.8e-12, equilibrium 2.7e-11.
  const std::vector<std::array<double, 3>> points{
      {0.3, 0.7, 0.5}, {-0.8, 0.2, 0.3}, {1.2, -0.4, 0.9}, {-0.1, -0.5, 0.6}};
  double worst_hooke = 0.0, worst_div = 0.0;
  for (double nu : {0.3, 0.0, -0.3}) {  // nu < 0.5: Hooke's law needs a finite lambda
    const auto b = [&](double x, double y, double z) { return boussinesq(x, y, z, nu); };
    const auto c = [&](double x, double y, double z) { return cerruti(x, y, z, nu); };
    for (const auto& p : points) {
      const double eh =
          std::max(max_difference(b(p[0], p[1], p[2]), hooke(boussinesq_u, p[0], p[1], p[2], nu)),
                   max_difference(c(p[0], p[1], p[2]), hooke(cerruti_u, p[0], p[1], p[2], nu)));
      double ed = 0.0;
      for (const auto& div :
           {divergence(b, p[0], p[1], p[2], 1e-3), divergence(c, p[0], p[1], p[2], 1e-3)})
        for (double v : div) ed = std::max(ed, std::abs(v));
      worst_hooke = std::max(worst_hooke, eh);
      worst_div = std::max(worst_div, ed);
      INFO("nu = " << nu << ", point (" << p[0] << ", " << p[1] << ", " << p[2] << ")");
      CHECK(eh <= 1e-9);
      CHECK(ed <= 1e-9);
      for (const Six& s : {b(p[0], p[1], 0.0), c(p[0], p[1], 0.0)}) {
        CHECK(s[2] == 0.0);
        CHECK(s[3] == 0.0);
        CHECK(s[4] == 0.0);
      }
    }
  }
  WARN("point forces, worst Hooke difference " << worst_hooke << ", equilibrium " << worst_div);
}

TEST_CASE("Hertz stress: the full field against the integrated point forces", "[hertz_stress]") {
  // Every component at interior points (under the contact, outside it, next to the axis where
  // the series in r are used) with friction 0.25, against Boussinesq's and Cerruti's fields
  // integrated over the contact (above). The quadrature's own error, measured by its change from
  // 160 to 240 nodes, is below 1e-13 p0; tolerance 1e-10 p0. Measured: 6.7e-15 p0.
  const std::vector<std::array<double, 3>> points{
      {0.3, 0.4, 0.5}, {-0.8, 0.3, 0.3}, {1.2, -0.5, 0.7}, {0.1, -0.05, 0.4}};
  double worst = 0.0;
  for (double nu : {0.3, 0.5}) {
    for (const auto& p : points) {
      const Six coarse = point_force_integral(p[0], p[1], p[2], nu, 0.25, 160);
      const Six ref = point_force_integral(p[0], p[1], p[2], nu, 0.25, 240);
      const double e = max_difference(stress(p[0], p[1], p[2], nu, 0.25), ref);
      worst = std::max(worst, e);
      INFO("nu = " << nu << ", (x, y, z)/a = (" << p[0] << ", " << p[1] << ", " << p[2] << ")");
      CHECK(max_difference(coarse, ref) <= 1e-13);
      CHECK(e <= 1e-10);
    }
  }
  WARN("full field against the point-force quadrature, worst error (of p0): " << worst);
}

TEST_CASE("Hertz stress: bad arguments", "[hertz_stress]") {
  using coatfft::InvalidArgument;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const auto call = [](double x, double y, double z, double p0, double a, double nu, double mu) {
    return hertz_sliding_stress(x, y, z, p0, a, nu, mu);
  };
  CHECK_NOTHROW(call(0, 0, 0, kPeakPressure, kContactRadius, 0.3, 0.25));
  CHECK_NOTHROW(call(0, 0, 0, kPeakPressure, kContactRadius, 0.5, -0.25));
  CHECK_THROWS_AS(call(0, 0, 0, kPeakPressure, 0.0, 0.3, 0.25), InvalidArgument);
  CHECK_THROWS_AS(call(0, 0, 0, kPeakPressure, -kContactRadius, 0.3, 0.25), InvalidArgument);
  CHECK_THROWS_AS(call(0, 0, 0, kPeakPressure, inf, 0.3, 0.25), InvalidArgument);
  CHECK_THROWS_AS(call(0, 0, -1e-12, kPeakPressure, kContactRadius, 0.3, 0.25), InvalidArgument);
  CHECK_THROWS_AS(call(0, 0, 0, kPeakPressure, kContactRadius, 0.5000001, 0.25), InvalidArgument);
  CHECK_THROWS_AS(call(0, 0, 0, kPeakPressure, kContactRadius, -1.0, 0.25), InvalidArgument);
  for (int i = 0; i < 7; ++i) {
    for (double bad : {nan, inf, -inf}) {
      std::array<double, 7> args{0.0, 0.0, 0.0, kPeakPressure, kContactRadius, 0.3, 0.25};
      args[static_cast<std::size_t>(i)] = bad;
      INFO("argument " << i << " = " << bad);
      CHECK_THROWS_AS(call(args[0], args[1], args[2], args[3], args[4], args[5], args[6]),
                      InvalidArgument);
    }
  }
}
