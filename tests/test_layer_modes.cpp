// The fields at depth per Fourier mode (LayerModes, docs/theory.md §2.7) against independent
// references: the homogeneous closed forms of §2.7, the surface FRFs (make_frf, MultilayerFrf,
// the anti-plane closed forms of §2.2-2.3), the plane-strain identity, equilibrium and Hooke's law
// by finite differences in z, interface conditions, and the thin and thick limits.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/layer_modes.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"

using coatfft::Coating;
using coatfft::Interface;
using coatfft::InterfaceSide;
using coatfft::InvalidArgument;
using coatfft::LayerModes;
using coatfft::LayerStack;
using coatfft::Material;
using coatfft::ModeFields;

namespace {

using Values = std::array<double, 15>;

Values values(const ModeFields& f) {
  return {f.uL_p,  f.uz_p,  f.szz_p, f.sLz_p, f.sLL_p, f.sTT_p, f.uL_q, f.uz_q,
          f.szz_q, f.sLz_q, f.sLL_q, f.sTT_q, f.uT_t,  f.sTz_t, f.sLT_t};
}

// Quantities of one kind share a scale at a point: p displacements, p stresses, q displacements,
// q stresses, u_T, SH stresses (indices into Values).
constexpr std::array<std::array<int, 2>, 6> kGroups{
    {{0, 2}, {2, 6}, {6, 8}, {8, 12}, {12, 13}, {13, 15}}};

int group_of(int i) {
  for (int g = 0; g < 6; ++g) {
    if (i >= kGroups[g][0] && i < kGroups[g][1]) return g;
  }
  return -1;
}

// The largest magnitude of each quantity's kind at that point.
Values kind_scales(const Values& v) {
  Values s{};
  for (const auto& [b, e] : kGroups) {
    double m = 0.0;
    for (int i = b; i < e; ++i) m = std::max(m, std::abs(v[i]));
    for (int i = b; i < e; ++i) s[i] = m;
  }
  return s;
}

// Homogeneous half-space, docs/theory.md §2.7 (closed forms, e = exp(-kz)).
ModeFields homogeneous(const Material& m, double k, double z) {
  const double nu = m.poisson_ratio(), mu = m.shear_modulus();
  const double kz = k * z, e = std::exp(-kz), d = 1.0 / (2.0 * mu * k);
  return {(1 - 2 * nu - kz) * e * d,
          (2 * (1 - nu) + kz) * e * d,
          -(1 + kz) * e,
          kz * e,
          -(1 - kz) * e,
          -2 * nu * e,
          (2 * (1 - nu) - kz) * e * d,
          (1 - 2 * nu + kz) * e * d,
          -kz * e,
          -(1 - kz) * e,
          -(2 - kz) * e,
          -2 * nu * e,
          e / (mu * k),
          -e,
          e};
}

// Largest error of `got` against `ref`, each quantity relative to the scale of its kind in ref.
double kind_error(const ModeFields& got, const ModeFields& ref) {
  const Values g = values(got), r = values(ref), s = kind_scales(r);
  double worst = 0.0;
  for (int i = 0; i < 15; ++i) worst = std::max(worst, std::abs(g[i] - r[i]) / s[i]);
  return worst;
}

bool all_finite(const ModeFields& f) {
  const Values v = values(f);
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// The stacks of the hard cases and the interface checks: contrasts both ways, nu = 0.4999, a
// frictionless interface between two bonded ones.
std::vector<LayerStack> test_stacks() {
  const Material steel(2.1e11, 0.3), soft(2.1e9, 0.3), rubber(5e6, 0.4999), tin(4e11, 0.25);
  const Material peek(3.6e9, 0.38), al(7e10, 0.33);
  return {
      LayerStack({{steel, 1e-6, Interface::bonded}}, soft),        // ratio 100
      LayerStack({{soft, 1e-6, Interface::bonded}}, steel),        // ratio 0.01
      LayerStack({{steel, 1e-6, Interface::frictionless}}, soft),  //
      LayerStack({{rubber, 1e-6, Interface::bonded}}, steel),      // nu = 0.4999
      LayerStack({{tin, 1e-6, Interface::bonded},                  //
                  {peek, 0.5e-6, Interface::frictionless},         //
                  {al, 2e-6, Interface::bonded}},                  //
                 soft),                                            // three layers
      LayerStack({{soft, 0.3e-6, Interface::frictionless}, {rubber, 1e-6, Interface::bonded}}, tin),
  };
}

// Depths inside every medium of `stack` at wavenumber k: fractions of each coating, the substrate.
std::vector<double> inner_depths(const LayerStack& stack, double k) {
  std::vector<double> d;
  double top = 0.0;
  for (const auto& c : stack.coatings()) {
    for (double f : {0.2, 0.5, 0.8}) d.push_back(top + f * c.thickness);
    top += c.thickness;
  }
  for (double kz : {0.3, 2.0}) d.push_back(top + kz / k);
  return d;
}

}  // namespace

TEST_CASE("LayerModes: homogeneous bodies give the closed forms of theory 2.7", "[frf][modes]") {
  // Closed forms vs the global solve: both round-off. At kz = 40 the rounding of k z alone is
  // ~40 ulps of exp(-kz) relative, hence 1e-13 relative to the largest coefficient of each kind
  // at that point; measured worst below.
  const Material m(7e10, 0.33);
  const LayerStack bare(m);
  // Coatings of the substrate's own material, bonded: thin (kh < 1) and thick branches at k = 2e6.
  const LayerStack same({{m, 0.2e-6, Interface::bonded},
                         {m, 1.5e-6, Interface::bonded},
                         {m, 0.05e-6, Interface::bonded}},
                        m);
  double worst = 0.0;
  for (const LayerStack* stack : {&bare, &same}) {
    const LayerModes modes(*stack);
    for (double k : {2e4, 2e6, 2e8}) {
      std::vector<double> z;
      for (double kz : {0.0, 1e-3, 0.05, 0.2, 0.4, 1.0, 2.0, 3.0, 3.5, 5.0, 10.0, 20.0, 30.0, 40.0})
        z.push_back(kz / k);
      for (double d : stack->interface_depths()) z.push_back(d);
      for (auto side : {InterfaceSide::above, InterfaceSide::below}) {
        const auto f = modes.at(k, z, side);
        for (std::size_t i = 0; i < z.size(); ++i) {
          const double e = kind_error(f[i], homogeneous(m, k, z[i]));
          worst = std::max(worst, e);
          INFO("coatings " << stack->coatings().size() << ", k = " << k << ", kz = " << k * z[i]);
          CHECK(e <= 1e-13);
        }
      }
    }
  }
  WARN("homogeneous closed forms, worst error relative to each kind's scale: " << worst);
}

TEST_CASE("LayerModes: the surface values are the surface FRFs", "[frf][modes]") {
  // uz_p(0) = H_zz(k) of make_frf (closed forms for one coating), (uL_q, uz_q, uL_p) = M of the
  // layer recursion (an independent algorithm), uT_t(0) = (C5) or coth(kh)/(mu1 k); tractions
  // exact. Measured <= 1.3e-14 over 900 random stacks while preparing this test.
  const Material sub(2e11, 0.3);
  double worst = 0.0, worst_t = 0.0;
  for (double ratio : {1e-4, 1e-2, 1.0, 100.0, 1e4}) {
    for (auto interface : {Interface::bonded, Interface::frictionless}) {
      const Material top(2e11 * ratio, 0.4999);
      const double h = 1e-6;
      const LayerStack stack({{top, h, interface}}, sub);
      const auto frf = coatfft::make_frf(stack);
      const coatfft::MultilayerFrf multi(stack);
      const LayerModes modes(stack);
      const double mu1 = top.shear_modulus(), m = mu1 / sub.shear_modulus();
      for (double kh : {1e-8, 1e-6, 1e-3, 0.1, 0.999, 1.001, 3.0, 50.0, 1e3, 1e4}) {
        const double k = kh / h, z0 = 0.0;
        const ModeFields f = modes.at(k, {&z0, 1})[0];
        const Eigen::Matrix2d M = multi.surface_compliance(k);
        // (C5) with gamma = (m - 1)/(m + 1) multiplied out, (1 + gamma X)/(1 - gamma X) =
        // (m (1 + X) + u)/(m u + 1 + X), u = 1 - X = -expm1(-2kh): as written, 1 + gamma X
        // cancels where m and kh are both small (5e-13 at m = 1e-4, kh = 1e-8).
        const double X = std::exp(-2.0 * kh), u = -std::expm1(-2.0 * kh);
        const double uT = interface == Interface::bonded
                              ? (m * (1.0 + X) + u) / (m * u + 1.0 + X) / (mu1 * k)
                              : 1.0 / (std::tanh(kh) * mu1 * k);
        const double cross = std::sqrt(M(0, 0) * M(1, 1));  // scale of the coupling terms
        const double e =
            std::max({std::abs(f.uz_p / (*frf)(k)-1.0), std::abs(f.uL_q / M(0, 0) - 1.0),
                      std::abs(f.uz_q - M(1, 0)) / cross, std::abs(f.uL_p - M(0, 1)) / cross,
                      std::abs(f.uT_t / uT - 1.0)});
        const double et = std::max({std::abs(f.szz_p + 1.0), std::abs(f.sLz_q + 1.0),
                                    std::abs(f.szz_q), std::abs(f.sLz_p), std::abs(f.sTz_t + 1.0)});
        worst = std::max(worst, e);
        worst_t = std::max(worst_t, et);
        INFO("E1/E2 = " << ratio << ", frictionless = " << (interface == Interface::frictionless)
                        << ", kh = " << kh);
        CHECK(e <= 1e-13);
        CHECK(et <= 1e-14);
      }
    }
  }
  // Several coatings: against MultilayerFrf (which make_frf returns for them).
  for (const LayerStack& stack : test_stacks()) {
    const coatfft::MultilayerFrf multi(stack);
    const LayerModes modes(stack);
    for (double k : {1e1, 1e4, 1e6, 3e6, 1e8, 1e10}) {
      const double z0 = 0.0;
      const ModeFields f = modes.at(k, {&z0, 1})[0];
      const Eigen::Matrix2d M = multi.surface_compliance(k);
      const double cross = std::sqrt(M(0, 0) * M(1, 1));
      const double e = std::max({std::abs(f.uz_p / M(1, 1) - 1.0), std::abs(f.uL_q / M(0, 0) - 1.0),
                                 std::abs(f.uz_q - M(1, 0)) / cross});
      worst = std::max(worst, e);
      INFO("coatings " << stack.coatings().size() << ", k = " << k);
      CHECK(e <= 1e-13);
    }
  }
  WARN("surface values vs FRFs, worst relative error: " << worst << "; tractions: " << worst_t);
}

TEST_CASE("LayerModes: sigma_yy = nu (sigma_xx + sigma_zz) in every medium", "[frf][modes]") {
  // Plane strain of the mode (docs/theory.md 2.7); exact for the rows of Barber's form, so
  // round-off relative to the larger of the two stresses.
  double worst = 0.0;
  for (const LayerStack& stack : test_stacks()) {
    const LayerModes modes(stack);
    std::vector<double> nus;
    for (const auto& c : stack.coatings()) nus.push_back(c.material.poisson_ratio());
    nus.push_back(stack.substrate().poisson_ratio());
    for (double k : {1e3, 1e6, 3e6, 1e8}) {
      const auto z = inner_depths(stack, k);
      const auto f = modes.at(k, z);
      for (std::size_t i = 0; i < z.size(); ++i) {
        const double nu = nus[std::min(i / 3, nus.size() - 1)];
        const double ep = std::abs(f[i].sTT_p - nu * (f[i].sLL_p + f[i].szz_p)) /
                          std::max(std::abs(f[i].sLL_p), std::abs(f[i].szz_p));
        const double eq = std::abs(f[i].sTT_q - nu * (f[i].sLL_q + f[i].szz_q)) /
                          std::max(std::abs(f[i].sLL_q), std::abs(f[i].szz_q));
        worst = std::max({worst, ep, eq});
        CHECK(ep <= 1e-14);
        CHECK(eq <= 1e-14);
      }
    }
  }
  WARN("plane-strain identity, worst relative residual: " << worst);
}

TEST_CASE("LayerModes: equilibrium and Hooke's law by finite differences in z", "[frf][modes]") {
  // For the mode exp(i k x) with u_x = i uL, sigma_xz = i sLz (real coefficients, both columns):
  //   d sLz/dz = -k sLL,   d szz/dz = k sLz,
  //   sLz = mu (d uL/dz + k uz),   szz = (lambda + 2 mu) d uz/dz - lambda k uL,
  //   sLL = lambda d uz/dz - (lambda + 2 mu) k uL;
  // anti-plane, u_T and sigma_LT = i sLT: d sTz/dz = k sLT, sTz = mu d uT/dz, sLT = mu k uT.
  // 5-point differences with k dz = 1e-3: truncation ~ (k dz)^4/30, rounding ~ 1e-16/(k dz);
  // 1e-10 relative to the size of the terms leaves a margin of 10 over the measured worst.
  double worst = 0.0;
  for (const LayerStack& stack : test_stacks()) {
    const LayerModes modes(stack);
    std::vector<Material> mats;
    for (const auto& c : stack.coatings()) mats.push_back(c.material);
    mats.push_back(stack.substrate());
    for (double k : {3e5, 1e6, 3e6}) {
      const auto centres = inner_depths(stack, k);
      for (std::size_t i = 0; i < centres.size(); ++i) {
        const double dz = 1e-3 / k;
        std::vector<double> z;
        for (int j = -2; j <= 2; ++j) z.push_back(centres[i] + j * dz);
        const auto f = modes.at(k, z);
        const Material& m = mats[std::min(i / 3, mats.size() - 1)];
        const double mu = m.shear_modulus(), nu = m.poisson_ratio();
        const double lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
        // The normal-stress relations weigh the displacements by lambda + 2 mu (2500 mu at
        // nu = 0.4999): their residuals are measured against that size of their terms.
        const double vol = (lambda + 2.0 * mu) / (2.0 * mu);
        const auto d = [&](auto get) {
          return (get(f[0]) - 8.0 * get(f[1]) + 8.0 * get(f[3]) - get(f[4])) / (12.0 * dz);
        };
        const ModeFields& c = f[2];
        const Values s = kind_scales(values(c));
        const double uP = s[0] * 2.0 * mu * k, sP = s[2], uQ = s[6] * 2.0 * mu * k, sQ = s[8];
        const double uT = s[12] * mu * k, sT = s[13];
        const std::array<double, 13> residuals{
            (d([](auto& x) { return x.sLz_p; }) + k * c.sLL_p) / (k * sP),
            (d([](auto& x) { return x.szz_p; }) - k * c.sLz_p) / (k * sP),
            (c.sLz_p - mu * (d([](auto& x) { return x.uL_p; }) + k * c.uz_p)) / std::max(sP, uP),
            (c.szz_p - (lambda + 2 * mu) * d([](auto& x) { return x.uz_p; }) +
             lambda * k * c.uL_p) /
                std::max(sP, vol * uP),
            (c.sLL_p - lambda * d([](auto& x) { return x.uz_p; }) +
             (lambda + 2 * mu) * k * c.uL_p) /
                std::max(sP, vol * uP),
            (d([](auto& x) { return x.sLz_q; }) + k * c.sLL_q) / (k * sQ),
            (d([](auto& x) { return x.szz_q; }) - k * c.sLz_q) / (k * sQ),
            (c.sLz_q - mu * (d([](auto& x) { return x.uL_q; }) + k * c.uz_q)) / std::max(sQ, uQ),
            (c.szz_q - (lambda + 2 * mu) * d([](auto& x) { return x.uz_q; }) +
             lambda * k * c.uL_q) /
                std::max(sQ, vol * uQ),
            (c.sLL_q - lambda * d([](auto& x) { return x.uz_q; }) +
             (lambda + 2 * mu) * k * c.uL_q) /
                std::max(sQ, vol * uQ),
            (d([](auto& x) { return x.sTz_t; }) - k * c.sLT_t) / (k * sT),
            (c.sTz_t - mu * d([](auto& x) { return x.uT_t; })) / std::max(sT, uT),
            (c.sLT_t - mu * k * c.uT_t) / std::max(sT, uT)};
        for (std::size_t r = 0; r < residuals.size(); ++r) {
          // Below a frictionless interface the anti-plane field is exactly 0 (0/0 here).
          if (r >= 10 && sT == 0.0 && c.uT_t == 0.0) continue;
          worst = std::max(worst, std::abs(residuals[r]));
          INFO("coatings " << stack.coatings().size() << ", k = " << k << ", z = " << centres[i]
                           << ", relation " << r);
          CHECK(std::abs(residuals[r]) <= 1e-10);
        }
      }
    }
  }
  WARN("equilibrium and Hooke's law, worst relative residual: " << worst);
}

TEST_CASE("LayerModes: interface conditions above and below", "[frf][modes]") {
  // Bonded: u_L, u_z, szz, sLz, u_T, sTz continuous; frictionless: u_z, szz continuous and
  // sLz = sTz = 0 on both faces. Round-off relative to each kind's scale at the interface.
  double worst = 0.0;
  for (const LayerStack& stack : test_stacks()) {
    const LayerModes modes(stack);
    const std::vector<double>& z = stack.interface_depths();
    std::vector<double> mu;
    for (const auto& c : stack.coatings()) mu.push_back(c.material.shear_modulus());
    mu.push_back(stack.substrate().shear_modulus());
    for (double k : {1e-2, 1e3, 1e6, 3e6, 1e8}) {
      const auto above = modes.at(k, z, InterfaceSide::above);
      const auto below = modes.at(k, z, InterfaceSide::below);
      for (std::size_t i = 0; i < z.size(); ++i) {
        const Values a = values(above[i]), b = values(below[i]);
        Values s = kind_scales(a);
        const Values sb = kind_scales(b);
        for (int q = 0; q < 15; ++q) s[q] = std::max(s[q], sb[q]);
        // A displacement is the sum of its medium's amplitudes (stress units) over 2 mu k: on
        // the soft side of a stiff interface it is a small difference of them, so its rounding
        // scale is the stress scale over 2 mu k of the softer medium (relative to u itself, a
        // soft rubber on TiN at kh = 100 differs by 1.3e-9 above vs below, as in 50-digit
        // arithmetic with z rounded by 1 ulp).
        const double mu_min = std::min(mu[i], mu[i + 1]);
        for (int q : {0, 1}) s[q] = std::max(s[q], s[2] / (2.0 * mu_min * k));
        for (int q : {6, 7}) s[q] = std::max(s[q], s[8] / (2.0 * mu_min * k));
        s[12] = std::max(s[12], s[13] / (mu_min * k));
        const bool bonded = stack.coatings()[i].interface_below == Interface::bonded;
        // Continuous: uL, uz, szz, sLz (p and q), uT, sTz if bonded; uz, szz if frictionless.
        const std::vector<int> continuous = bonded
                                                ? std::vector<int>{0, 1, 2, 3, 6, 7, 8, 9, 12, 13}
                                                : std::vector<int>{1, 2, 7, 8};
        double e = 0.0;
        for (int q : continuous) e = std::max(e, std::abs(a[q] - b[q]) / s[q]);
        if (!bonded) {
          for (int q : {3, 9, 13}) e = std::max({e, std::abs(a[q]) / s[q], std::abs(b[q]) / s[q]});
          // At small k h the layer slides: its u_L differs from the medium below's.
          if (k <= 1e3) CHECK(std::abs(a[6] - b[6]) > 0.5 * std::abs(a[6]));
        }
        worst = std::max(worst, e);
        INFO("coatings " << stack.coatings().size() << ", interface " << i + 1 << ", k = " << k);
        CHECK(e <= 1e-13);
      }
    }
  }
  WARN("interface conditions, worst relative residual: " << worst);
}

TEST_CASE("LayerModes: hard cases stay finite and take their limits", "[frf][modes]") {
  const auto stacks = test_stacks();
  // k h from 1e-8 to 1e4 (h = the top coating's thickness): every coefficient finite at every
  // depth and both sides of every interface.
  for (const LayerStack& stack : stacks) {
    const LayerModes modes(stack);
    const double h = stack.coatings().front().thickness;
    for (double kh = 1e-8; kh <= 1.5e4; kh *= 10.0) {
      const double k = kh / h;
      std::vector<double> z = inner_depths(stack, k);
      for (double d : stack.interface_depths()) z.push_back(d);
      z.push_back(0.0);
      z.push_back(1e3 / k);
      for (auto side : {InterfaceSide::above, InterfaceSide::below}) {
        for (const ModeFields& f : modes.at(k, z, side)) {
          INFO("coatings " << stack.coatings().size() << ", kh = " << kh);
          CHECK(all_finite(f));
        }
      }
    }
  }
  double worst_thick = 0.0, worst_thin = 0.0;
  // k h -> inf: inside the top coating (fixed kz) the field is the top material's homogeneous one,
  // up to exp(-2 k h) = 0 in double at kh = 1e4.
  for (const LayerStack& stack : stacks) {
    const LayerModes modes(stack);
    const Material& top = stack.coatings().front().material;
    const double k = 1e4 / stack.coatings().front().thickness;
    std::vector<double> z;
    for (double kz : {0.0, 0.5, 2.0, 10.0}) z.push_back(kz / k);
    const auto f = modes.at(k, z);
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double e = kind_error(f[i], homogeneous(top, k, z[i]));
      worst_thick = std::max(worst_thick, e);
      INFO("coatings " << stack.coatings().size() << ", kz = " << k * z[i]);
      CHECK(e <= 1e-13);
    }
  }
  // k h -> 0: inside the substrate (fixed k zeta below its top) the field is the substrate's
  // homogeneous one with an O(k h_total) difference (k h_total = 1e-10 here); all columns for
  // bonded stacks, the pressure columns with a frictionless interface (which carries no shear: a
  // q_L load slides the layers).
  for (const LayerStack& stack : stacks) {
    const LayerModes modes(stack);
    const double H = stack.total_thickness();
    const double k = 1e-10 / H;
    bool bonded = true;
    for (const auto& c : stack.coatings()) bonded &= c.interface_below == Interface::bonded;
    for (double kzeta : {0.0, 0.5, 3.0}) {
      const double z = H + kzeta / k;
      const ModeFields f = modes.at(k, {&z, 1})[0];
      ModeFields ref = homogeneous(stack.substrate(), k, kzeta / k);
      const Values g = values(f), r = values(ref), s = kind_scales(r);
      for (int q = 0; q < 15; ++q) {
        if (!bonded && group_of(q) >= 2) continue;
        INFO("coatings " << stack.coatings().size() << ", k zeta = " << kzeta << ", quantity "
                         << q);
        worst_thin = std::max(worst_thin, std::abs(g[q] - r[q]) / s[q]);
        CHECK(std::abs(g[q] - r[q]) <= 1e-6 * s[q]);
      }
    }
  }
  WARN("limits: top coating at kh = 1e4 " << worst_thick << ", substrate at k h_total = 1e-10 "
                                          << worst_thin);
}

TEST_CASE("LayerModes: the hard cases agree with the surface FRFs and are continuous",
          "[frf][modes]") {
  // kh = 1e-3 at E ratio 100 and 0.01, kh = 50 at 0.01, nu = 0.4999, three layers with a
  // frictionless interface in the middle: the surface values against MultilayerFrf (measured
  // <= 1e-14 in the test above), every coefficient finite inside every medium.
  const auto stacks = test_stacks();
  for (std::size_t n : {0u, 1u, 2u, 3u, 4u}) {
    const LayerStack& stack = stacks[n];
    const LayerModes modes(stack);
    const coatfft::MultilayerFrf multi(stack);
    const double h = stack.coatings().front().thickness;
    for (double kh : {1e-3, 50.0}) {
      const double k = kh / h;
      std::vector<double> z = inner_depths(stack, k);
      z.insert(z.begin(), 0.0);
      const auto f = modes.at(k, z);
      const Eigen::Matrix2d M = multi.surface_compliance(k);
      INFO("stack " << n << ", kh = " << kh);
      CHECK(std::abs(f[0].uz_p / M(1, 1) - 1.0) <= 1e-13);
      CHECK(std::abs(f[0].uL_q / M(0, 0) - 1.0) <= 1e-13);
      for (const ModeFields& g : f) CHECK(all_finite(g));
    }
  }
}

TEST_CASE("LayerModes: the medium of an interface depth follows InterfaceSide", "[frf][modes]") {
  // A stiff coating on a soft substrate: sLL jumps at the interface, by the contrast of moduli.
  const LayerStack stack({{Material(2e11, 0.3), 1e-6, Interface::bonded}}, Material(2e9, 0.3));
  const LayerModes modes(stack);
  const double z = 1e-6, k = 1e6;
  const ModeFields a = modes.at(k, {&z, 1}, InterfaceSide::above)[0];
  const ModeFields b = modes.at(k, {&z, 1}, InterfaceSide::below)[0];
  const ModeFields d = modes.at(k, {&z, 1})[0];
  CHECK(std::abs(a.sLL_p) > 10.0 * std::abs(b.sLL_p));
  CHECK(d.sLL_p == b.sLL_p);  // below is the default
  // The surface belongs to the top coating either way.
  const double z0 = 0.0;
  CHECK(modes.at(k, {&z0, 1}, InterfaceSide::above)[0].uz_p ==
        modes.at(k, {&z0, 1}, InterfaceSide::below)[0].uz_p);
}

TEST_CASE("LayerModes: a typed depth equal to a running-sum interface is that interface",
          "[frf][modes][interface]") {
  // 10e-6 + 20e-6 = 3.0000000000000004e-5 (the typed 3e-5 is one ulp above, in the middle
  // coating) and 7e-6 + 3e-6 = 9.999999999999999e-6 (1e-5 one ulp below, in the substrate):
  // within LayerStack::locate's tolerance, both are the interface on the side asked, with the
  // interface's own fields bit for bit.
  const Material stiff(4e11, 0.25), soft(5e10, 0.3), steel(2.1e11, 0.3);
  const LayerStack up({{stiff, 10e-6, Interface::bonded}, {soft, 20e-6, Interface::bonded}}, steel);
  const LayerStack down({{stiff, 7e-6, Interface::bonded}, {soft, 3e-6, Interface::bonded}}, steel);
  for (const auto& [stack, typed] : {std::pair{&up, 30e-6}, std::pair{&down, 10e-6}}) {
    const LayerModes modes(*stack);
    const double exact = stack->interface_depths()[1];
    REQUIRE(exact != typed);
    for (const double k : {1e3, 1e5, 3e5}) {
      const double z[2] = {typed, exact};
      const auto a = modes.at(k, z, InterfaceSide::above);
      const auto b = modes.at(k, z, InterfaceSide::below);
      CHECK(values(a[0]) == values(a[1]));
      CHECK(values(b[0]) == values(b[1]));
      CHECK(std::abs(a[0].sLL_p - b[0].sLL_p) > 0.1 * std::abs(b[0].sLL_p));
    }
  }
}

TEST_CASE("LayerModes refuses bad wavenumbers and depths", "[frf][modes]") {
  const LayerModes modes(
      LayerStack({{Material(2e11, 0.3), 1e-6, Interface::bonded}}, Material(2e9, 0.3)));
  const double ok = 1e-6;
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double k : {0.0, -1.0, inf, nan}) {
    INFO("k = " << k);
    REQUIRE_THROWS_AS(modes.at(k, {&ok, 1}), InvalidArgument);
  }
  for (double z : {-1e-9, -inf, inf, nan}) {
    const std::vector<double> depths{0.0, z};
    INFO("z = " << z);
    REQUIRE_THROWS_AS(modes.at(1e6, depths), InvalidArgument);
  }
  CHECK(modes.at(1e6, std::vector<double>{}).empty());
}
