#pragma once
// Homogeneous elastic half-space: H(k) = 2 (1 - nu^2) / (E k) = 2 / (E* k)  (docs/theory.md (1.2)).
#include <string>

#include "../materials/material.hpp"
#include "frf.hpp"

namespace coatfft {

class HalfSpaceFrf final : public Frf {
 public:
  explicit HalfSpaceFrf(const Material& material);

  /// H(k) = 2 / (E* k) [m/Pa] for k > 0 [rad/m]; throws InvalidArgument for k <= 0 or not finite.
  double operator()(double k) const override;
  double c0() const override { return c_; }     ///< 2 / E* [1/Pa]
  double c_inf() const override { return c_; }  ///< 2 / E* [1/Pa]
  std::string name() const override { return "half_space"; }

 private:
  double c_;  // 2 / E* [1/Pa]
};

}  // namespace coatfft
