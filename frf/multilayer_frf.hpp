#pragma once
// N coatings (any mix of bonded and frictionless interfaces) on a substrate, by a
// surface-compliance recursion from the substrate up (docs/theory.md §2.4, alternative 2). Each
// layer is crossed either with its analytic propagator (k h_j <= 1, where it is exact and well
// conditioned) or with the local decaying-exponential basis of docs/theory.md §2.1 (k h_j > 1,
// where only exp(-k h_j) appears), so no step overflows or loses digits for any k h_j. O(N) per
// wavenumber with 4x4 fixed-size algebra.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "../layers/layer_stack.hpp"
#include "frf.hpp"

namespace coatfft {

class MultilayerFrf final : public Frf {
 public:
  /// Any stack; a homogeneous one gives the half-space FRF (make_frf picks cheaper classes).
  explicit MultilayerFrf(const LayerStack& stack);

  /// H_zz(k) = u_z^/p^ [m/Pa] for k > 0 [rad/m]; throws for k <= 0 or not finite.
  double operator()(double k) const override;
  double c0() const override { return c0_; }        ///< 2 / E*_substrate [1/Pa]
  double c_inf() const override { return c_inf_; }  ///< 2 / E*_top coating [1/Pa]
  std::string name() const override { return "multilayer"; }

  /// The real 2x2 surface compliance M(k) [m/Pa] of the P-SV part (docs/theory.md §2.1):
  /// [-i u_L, u_z]^ = M [-i q_L, p]^, so u_L/q_L = M(0,0), u_z/p = M(1,1), H_ZL = M(1,0) = M(0,1).
  Eigen::Matrix2d surface_compliance(double k) const;

 private:
  struct Layer {
    double thickness;  // [m]
    double nu;
    double two_mu;  // 2 mu [Pa]
    double gamma;   // 1 / (2 (1 - nu))
    Interface interface_below;
  };
  std::vector<Layer> layers_;     // top first
  Eigen::Matrix2d substrate_kG_;  // k * compliance of the bare substrate [1/Pa]
  double c0_;
  double c_inf_;
};

}  // namespace coatfft
