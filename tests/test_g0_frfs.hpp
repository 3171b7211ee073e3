#pragma once
// Test-local FRFs for the g(0) and FRF-pipeline tests: the homogeneous half-space and one coating
// on a substrate, bonded (docs/theory.md C1) or frictionless (C2). They are written here from
// docs/theory.md, independently of frf/, so that these tests do not depend on another module's
// state; test_g0.cpp checks them against the 40-digit values of frf_values.csv.
#include <cmath>
#include <string>

#include "frf/frf.hpp"

namespace coatfft::testing {

class InverseKFrf final : public Frf {
 public:
  explicit InverseKFrf(double E_star) : c_(2.0 / E_star) {}
  double operator()(double k) const override { return c_ / k; }
  double c0() const override { return c_; }
  double c_inf() const override { return c_; }
  std::string name() const override { return "test_half_space"; }

 private:
  double c_;
};

/// One coating (E1, nu1, thickness h) on a substrate (E2, nu2).
class CoatingFrf final : public Frf {
 public:
  CoatingFrf(double E1, double nu1, double E2, double nu2, double h, bool bonded)
      : e1s_(E1 / (1 - nu1 * nu1)), e2s_(E2 / (1 - nu2 * nu2)), h_(h), bonded_(bonded) {
    const double mu1 = E1 / (2 * (1 + nu1)), mu2 = E2 / (2 * (1 + nu2));
    const double m = mu1 / mu2, k1 = 3 - 4 * nu1, k2 = 3 - 4 * nu2;
    alpha_ = (m * k2 - k1) / (m * k2 + 1);
    beta_ = (m - 1) / (m + k1);
  }
  /// C(t) = H E1* k / 2 at t = k h.
  double c_of_t(double t) const {
    const double X = std::exp(-2 * t);
    if (bonded_) {
      const double D = 1 - (alpha_ + beta_ + 4 * beta_ * t * t) * X + alpha_ * beta_ * X * X;
      return (1 + 4 * beta_ * t * X - alpha_ * beta_ * X * X) / D;
    }
    const double R = e1s_ / e2s_, omx = -std::expm1(-2 * t);
    const double D = (1 - X * X) + 4 * t * X + R * (omx * omx - 4 * t * t * X);
    return (R * (1 - X * X + 4 * t * X) + omx * omx) / D;
  }
  double operator()(double k) const override { return 2 * c_of_t(k * h_) / (e1s_ * k); }
  double c0() const override { return 2 / e2s_; }
  double c_inf() const override { return 2 / e1s_; }
  std::string name() const override { return bonded_ ? "test_bonded" : "test_frictionless"; }

 private:
  double e1s_, e2s_, h_;
  bool bonded_;
  double alpha_ = 0, beta_ = 0;
};

}  // namespace coatfft::testing
