#include "frf/multilayer_frf.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "frf/detail/hyperbolic_series.hpp"

namespace coatfft {

namespace {

using Matrix42 = Eigen::Matrix<double, 4, 2>;
using Matrix24 = Eigen::Matrix<double, 2, 4>;

// State vector at a depth: s = (U, W, S, T) = (2 mu k (-i u_x), 2 mu k u_z, sigma_zz, -i sigma_xz)
// for the Fourier mode exp(i k x), with mu the shear modulus of the layer being crossed; a body
// loaded on its top face by (q~, p) has sigma_xz~ = -q~, sigma_zz = -p there (docs/theory.md §2.1).
// "kG" is k times a surface compliance: [U, W]/(2 mu) = kG [q~, p].

// Above this kh_j the propagator is replaced by the decaying basis; both are accurate around 1.
constexpr double kThinLayerKh = 1.0;
using detail::min_kh;
// exp(-kh) underflows to zero beyond ~745; kh exp(-kh) is then set to zero explicitly.
constexpr double kExpUnderflowKh = 700.0;

// Basis of the admissible states at the bottom of a layer, in the layer's scaled units, given the
// body below: bonded -> continuity of (u, sigma) with u = G (-sigma); frictionless -> sigma_xz = 0,
// u_z = G_zz (-sigma_zz), u_x free.
Matrix42 bottom_basis(const Eigen::Matrix2d& kG, Interface interface, double two_mu) {
  Matrix42 Y = Matrix42::Zero();
  if (interface == Interface::bonded) {  // parameters (q~, p) of the body below
    Y(0, 0) = two_mu * kG(0, 0);
    Y(0, 1) = two_mu * kG(0, 1);
    Y(1, 0) = two_mu * kG(1, 0);
    Y(1, 1) = two_mu * kG(1, 1);
    Y(2, 1) = -1.0;
    Y(3, 0) = -1.0;
  } else {  // parameters (U, p)
    Y(0, 0) = 1.0;
    Y(1, 1) = two_mu * kG(1, 1);
    Y(2, 1) = -1.0;
  }
  return Y;
}

// The same admissible set as two linear constraints K s = 0.
Matrix24 bottom_constraints(const Eigen::Matrix2d& kG, Interface interface, double two_mu) {
  Matrix24 K = Matrix24::Zero();
  if (interface == Interface::bonded) {  // U + 2mu (G00 T + G01 S) = 0, W + 2mu (G10 T + G11 S) = 0
    K << 1.0, 0.0, two_mu * kG(0, 1), two_mu * kG(0, 0),  //
        0.0, 1.0, two_mu * kG(1, 1), two_mu * kG(1, 0);
  } else {                    // T = 0, W + 2mu G11 S = 0
    K << 0.0, 0.0, 0.0, 1.0,  //
        0.0, 1.0, two_mu * kG(1, 1), 0.0;
  }
  return K;
}

// k * compliance at the top of the layer from the admissible set Y at the top: loads
// (q~, p) = -(T, S) and displacements (U, W)/(2 mu) are both linear in the two parameters.
Eigen::Matrix2d compliance_from_top_states(const Matrix42& Ytop, double two_mu) {
  Eigen::Matrix2d V = Ytop.topRows<2>() / two_mu;
  Eigen::Matrix2d L;
  L.row(0) = -Ytop.row(3);
  L.row(1) = -Ytop.row(2);
  return V * L.inverse();
}

}  // namespace

MultilayerFrf::MultilayerFrf(const LayerStack& stack)
    : c0_(2.0 / stack.substrate().plane_strain_modulus()),
      c_inf_(2.0 / (stack.is_homogeneous() ? stack.substrate() : stack.coatings().front().material)
                       .plane_strain_modulus()) {
  for (const auto& coating : stack.coatings()) {
    const Material& mat = coating.material;
    layers_.push_back({coating.thickness, mat.poisson_ratio(), 2.0 * mat.shear_modulus(),
                       1.0 / (2.0 * (1.0 - mat.poisson_ratio())), coating.interface_below});
  }
  // Homogeneous half-space (docs/theory.md (1.3)): u_L/q_L = u_z/p = (1-nu)/(mu k), cross terms
  // (1-2nu)/(2 mu k), written for the real variables (-i u_x, u_z) and (-i q_x, p).
  const double nu = stack.substrate().poisson_ratio();
  const double mu = stack.substrate().shear_modulus();
  substrate_kG_ << (1.0 - nu) / mu, (1.0 - 2.0 * nu) / (2.0 * mu),  //
      (1.0 - 2.0 * nu) / (2.0 * mu), (1.0 - nu) / mu;
}

Eigen::Matrix2d MultilayerFrf::surface_compliance(double k) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "MultilayerFrf: k = ", k,
                  " rad/m, but the wavenumber must be finite and > 0");
  Eigen::Matrix2d kG = substrate_kG_;
  for (auto it = layers_.rbegin(); it != layers_.rend(); ++it) {
    const Layer& layer = *it;
    const double t = std::max(k * layer.thickness, min_kh);
    const double nu = layer.nu;
    const double g = layer.gamma;
    if (t <= kThinLayerKh) {
      // Propagator from the bottom (depth t) to the top, P(-t) with P(z) = Phi(z) Phi(0)^-1 of the
      // Papkovich-Neuber solution (derived with sympy; checked against the global-matrix solve).
      // With z = -t: c = cosh t, s = -sinh t, zs = t sinh t, zc = -t cosh t, w = z cosh z - sinh z.
      const double c = std::cosh(t);
      const double s = -std::sinh(t);
      const double zs = t * std::sinh(t);
      const double zc = -t * c;
      const double w = -detail::x_cosh_minus_sinh(t);
      const double k1 = 1.0 - 2.0 * nu;
      Eigen::Matrix4d P;
      P << c + g * zs, -g * (k1 * s + zc), -g * zs, g * ((3.0 - 4.0 * nu) * s + zc),  //
          g * (w + 2.0 * nu * s), c - g * zs, g * (2.0 * k1 * s - w), g * zs,         //
          g * zs, -g * w, c - g * zs, g * (k1 * s + zc),                              //
          g * (zc + s), -g * zs, -g * (w + 2.0 * nu * s), c + g * zs;
      const Matrix42 Ytop = P * bottom_basis(kG, layer.interface_below, layer.two_mu);
      kG = compliance_from_top_states(Ytop, layer.two_mu);
    } else {
      // Local decaying basis (docs/theory.md §2.1): amplitudes (A, B) of the pair referenced to the
      // top and (C, D) of the pair referenced to the bottom; columns = unit amplitudes.
      const double e = t < kExpUnderflowKh ? std::exp(-t) : 0.0;
      const double te = t < kExpUnderflowKh ? t * e : 0.0;
      const double kap = 3.0 - 4.0 * nu;
      const double two_one_minus_nu = 2.0 * (1.0 - nu);
      const double k1 = 1.0 - 2.0 * nu;
      Eigen::Matrix4d top;                                       // state at zeta = 0 (eta = h)
      top << 1.0, 0.0, e, -te,                                   //
          -1.0, -kap, e, -te - kap * e,                          //
          1.0, two_one_minus_nu, e, -te - two_one_minus_nu * e,  //
          -1.0, -k1, e, -te - k1 * e;
      Eigen::Matrix4d bottom;                                    // state at eta = 0 (zeta = h)
      bottom << e, te, 1.0, 0.0,                                 //
          -e, -te - kap * e, 1.0, -kap,                          //
          e, te + two_one_minus_nu * e, 1.0, -two_one_minus_nu,  //
          -e, -te - k1 * e, 1.0, -k1;
      Eigen::Matrix4d M;
      M.topRows<2>() = bottom_constraints(kG, layer.interface_below, layer.two_mu) * bottom;
      M.bottomRows<2>() = top.middleRows<2>(2);
      Matrix42 rhs = Matrix42::Zero();  // columns: (q~, p) = (1, 0) and (0, 1); S = -p, T = -q~
      rhs(2, 1) = -1.0;
      rhs(3, 0) = -1.0;
      const Matrix42 amplitudes = M.partialPivLu().solve(rhs);
      kG = (top.topRows<2>() * amplitudes) / layer.two_mu;
    }
  }
  return kG / k;
}

double MultilayerFrf::operator()(double k) const {
  const double h = surface_compliance(k)(1, 1);
  COATFFT_REQUIRE(std::isfinite(h) && h > 0, "MultilayerFrf: H(k = ", k, " rad/m) = ", h,
                  " is not finite and positive");
  return h;
}

}  // namespace coatfft
