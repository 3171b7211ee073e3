#pragma once
// One coating (E1, nu1, thickness h) on a substrate (E2, nu2), bonded or frictionless interface:
// closed forms (C1) and (C2) of docs/theory.md §2.2-2.3 (Chen & Engel 1972; O'Sullivan & King 1988;
// Perriot & Barthel 2004; Yu, Wang & Wang 2014), H(k) = 2 C(kh) / (E1* k).
#include <string>

#include "../layers/layer_stack.hpp"
#include "../materials/material.hpp"
#include "frf.hpp"

namespace coatfft {

class CoatedFrf final : public Frf {
 public:
  /// thickness [m], finite and > 0 (throws InvalidArgument otherwise).
  CoatedFrf(const Material& coating, double thickness, const Material& substrate,
            Interface interface);

  /// H(k) = 2 C(k h) / (E1* k) [m/Pa] for k > 0 [rad/m]; throws for k <= 0 or not finite.
  double operator()(double k) const override;
  double c0() const override { return 2.0 / substrate_E_star_; }   ///< 2 / E2* [1/Pa]
  double c_inf() const override { return 2.0 / coating_E_star_; }  ///< 2 / E1* [1/Pa]
  std::string name() const override;

  /// Dimensionless factor C(t) = H E1* k / 2 at t = k h >= 0 [-]: C(0) = E1*/E2*, C(inf) = 1.
  /// Accurate to a few ulps for every t (no cancellation; see docs/frf.md).
  double factor(double kh) const;
  /// C(t) - 1 [-], accurate also where C is close to 1 (large t), e.g. for H - c_inf()/k.
  double factor_minus_one(double kh) const;

  double thickness() const { return thickness_; }  ///< h [m]
  Interface interface() const { return interface_; }

 private:
  double thickness_;
  Interface interface_;
  double coating_E_star_;
  double substrate_E_star_;
  double R_;  // E1* / E2*
  // Bonded constants (docs/theory.md §2.2): alpha, beta and, computed without cancellation,
  // a = 1 - alpha, b = 1 - beta, 1 + alpha, 1 - alpha beta, a beta + b alpha (= alpha + beta - 2
  // alpha beta).
  double alpha_ = 0, beta_ = 0, a_ = 0, b_ = 0, one_plus_alpha_ = 0, one_minus_ab_ = 0,
         a_beta_plus_b_alpha_ = 0;
};

}  // namespace coatfft
