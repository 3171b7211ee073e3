#include "frf/coated_frf.hpp"

#include <cmath>

#include "core/error.hpp"
#include "frf/detail/hyperbolic_series.hpp"

namespace coatfft {

namespace {

// Beyond this kh, X = exp(-2 kh) < 1e-347 underflows to 0 and C - 1 = 0 exactly in double;
// returning early also keeps t^2 finite for absurd kh (t^2 X would be inf * 0).
constexpr double kLargeKh = 400.0;

// The exponential building blocks at t = kh, each computed without cancellation:
//   X = exp(-2t), u = 1 - X, Q = 4 X (sinh^2 t - t^2) = u^2 - 4 t^2 X,
//   P = X (sinh 2t - 2t),  S = 2 X (sinh 2t + 2t) = u (1 + X) + 4 t X.
struct Blocks {
  double X, u, Q, P, S;
};

Blocks blocks(double t) {
  Blocks b{};
  b.X = std::exp(-2.0 * t);
  b.u = -std::expm1(-2.0 * t);
  // For t >= 1, u^2 >= 0.75 and 4 t^2 X <= 0.55 u^2: at most ~2 bits lost.
  b.Q = t < 1.0 ? 4.0 * b.X * detail::sinh_minus_x(t) * (std::sinh(t) + t)
                : b.u * b.u - 4.0 * t * t * b.X;
  b.P =
      2.0 * t < 1.0 ? b.X * detail::sinh_minus_x(2.0 * t) : 0.5 * b.u * (1.0 + b.X) - 2.0 * t * b.X;
  b.S = b.u * (1.0 + b.X) + 4.0 * t * b.X;
  return b;
}

}  // namespace

CoatedFrf::CoatedFrf(const Material& coating, double thickness, const Material& substrate,
                     Interface interface)
    : thickness_(thickness),
      interface_(interface),
      coating_E_star_(coating.plane_strain_modulus()),
      substrate_E_star_(substrate.plane_strain_modulus()),
      R_(coating.plane_strain_modulus() / substrate.plane_strain_modulus()) {
  COATFFT_REQUIRE(std::isfinite(thickness) && thickness > 0, "CoatedFrf: thickness = ", thickness,
                  " m, but the coating thickness must be finite and > 0");
  const double m = coating.shear_modulus() / substrate.shear_modulus();
  const double k1 = coating.kolosov();
  const double k2 = substrate.kolosov();
  const double nu1 = coating.poisson_ratio();
  alpha_ = (m * k2 - k1) / (m * k2 + 1.0);
  beta_ = (m - 1.0) / (m + k1);
  // Hand algebra of docs/theory.md §2.6(b); these differences vanish for a rigid or a compliant
  // substrate and must not be formed by subtraction. 1 - 2 nu1 is exact in floating point for
  // nu1 in [1/4, 1/2), which keeps 1 + alpha accurate for nearly incompressible coatings.
  a_ = (1.0 + k1) / (m * k2 + 1.0);
  b_ = (1.0 + k1) / (m + k1);
  one_plus_alpha_ = 2.0 * (m * k2 - (1.0 - 2.0 * nu1)) / (m * k2 + 1.0);
  one_minus_ab_ = m * (1.0 + k1) * (1.0 + k2) / ((m * k2 + 1.0) * (m + k1));
  a_beta_plus_b_alpha_ = a_ * beta_ + b_ * alpha_;
}

std::string CoatedFrf::name() const {
  return interface_ == Interface::bonded ? "coated_bonded" : "coated_frictionless";
}

double CoatedFrf::factor_minus_one(double kh) const {
  COATFFT_REQUIRE(kh >= 0 && !std::isnan(kh), "CoatedFrf: kh = ", kh, ", but kh must be >= 0");
  if (kh > kLargeKh) return 0.0;
  const double t = kh;
  const Blocks e = blocks(t);
  if (interface_ == Interface::bonded) {
    // (C1) with 1 - (alpha + beta) X + alpha beta X^2 = (u + a X)(u + b X), u^2 - 4 t^2 X = Q and
    // beta = 1 - b: every term of D is >= 0 because a, b > 0 for -1 < nu < 1/2.
    const double D = e.Q + (a_ + b_) * e.u * e.X + a_ * b_ * e.X * e.X + 4.0 * b_ * t * t * e.X;
    // N - D = X [alpha + beta - 2 alpha beta X + 4 beta t (1 + t)], with
    // alpha + beta - 2 alpha beta X = (a beta + b alpha) + 2 alpha beta u.
    const double NmD =
        e.X * (a_beta_plus_b_alpha_ + 2.0 * alpha_ * beta_ * e.u + 4.0 * beta_ * t * (1.0 + t));
    return NmD / D;
  }
  // (C2): C_f - 1 = 2X [(R - 1)(1 - X + 2t) + 2 R t^2] / D_f, D_f = S + R Q (all terms >= 0).
  const double D = e.S + R_ * e.Q;
  return 2.0 * e.X * ((R_ - 1.0) * (e.u + 2.0 * t) + 2.0 * R_ * t * t) / D;
}

double CoatedFrf::factor(double kh) const {
  COATFFT_REQUIRE(kh >= 0 && !std::isnan(kh), "CoatedFrf: kh = ", kh, ", but kh must be >= 0");
  if (kh > kLargeKh) return 1.0;
  const double t = kh;
  const Blocks e = blocks(t);
  if (interface_ == Interface::bonded) {
    const double D = e.Q + (a_ + b_) * e.u * e.X + a_ * b_ * e.X * e.X + 4.0 * b_ * t * t * e.X;
    const double NmD =
        e.X * (a_beta_plus_b_alpha_ + 2.0 * alpha_ * beta_ * e.u + 4.0 * beta_ * t * (1.0 + t));
    const double c = 1.0 + NmD / D;
    if (c >= 0.5) return c;
    // C well below 1 (compliant coating on a stiffer substrate): 1 + (C - 1) would lose
    // log10(1/C) digits, so use N directly, N = 1 + 4 beta t X - alpha beta X^2 rewritten as
    // (1 - alpha beta) + beta [(1 + alpha)(1 - X^2) - 2 X (sinh 2t - 2t)]; the last bracket holds
    // the squeeze-film cancellation of a nearly incompressible coating in closed form.
    const double N = one_minus_ab_ + beta_ * (one_plus_alpha_ * e.u * (1.0 + e.X) - 2.0 * e.P);
    return N / D;
  }
  // (C2) as N_f / D_f with N_f = R S + u^2 and D_f = S + R Q: sums of non-negative terms.
  return (R_ * e.S + e.u * e.u) / (e.S + R_ * e.Q);
}

double CoatedFrf::operator()(double k) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "CoatedFrf: k = ", k,
                  " rad/m, but the wavenumber must be finite and > 0");
  const double h = 2.0 * factor(k * thickness_) / (coating_E_star_ * k);
  COATFFT_REQUIRE(std::isfinite(h), "CoatedFrf: H(k = ", k, " rad/m) overflows");
  return h;
}

}  // namespace coatfft
