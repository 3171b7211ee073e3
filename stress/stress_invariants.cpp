#include "stress/stress_invariants.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace coatfft {

namespace {

double unscaled_von_mises(const StressVector& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// The symmetric tensor of s's six components (xx, yy, zz, yz, xz, xy).
Eigen::Matrix3d tensor(const StressVector& s) {
  Eigen::Matrix3d m;
  m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
  return m;
}

// The symmetric solvers' eigenvalues come sorted increasingly.
std::array<double, 3> largest_first(const Eigen::Vector3d& e) {
  return {e[2], e[1], e[0]};
}

}  // namespace

double von_mises(const StressVector& s) {
  // Scaled by the largest component, as std::hypot is: the squares of stresses above ~1e154 Pa
  // (and the differences of ones near 1e308 Pa) overflow though the result is representable, and
  // those of stresses below ~1e-154 Pa underflow. The scale is a power of two, so that scaling is
  // exact and other stresses give the unscaled formula's value. A NaN or an infinity is passed on.
  double scale = 0.0;
  bool finite = true;
  for (const double v : s) {
    scale = std::max(scale, std::abs(v));
    finite = finite && std::isfinite(v);
  }
  if (!finite || scale == 0.0) return unscaled_von_mises(s);
  // Far from both ends the scaling changes nothing (a power of two scales every rounding alike):
  // skipped, as it is the costly part.
  if (scale > 1e-100 && scale < 1e100) return unscaled_von_mises(s);
  int exponent = 0;
  std::frexp(scale, &exponent);
  StressVector t;
  for (std::size_t i = 0; i < s.size(); ++i) t[i] = std::ldexp(s[i], -exponent);
  return std::ldexp(unscaled_von_mises(t), exponent);
}

std::array<double, 3> principal_stresses(const StressVector& s) {
  const Eigen::Vector3d e =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor(s), Eigen::EigenvaluesOnly)
          .eigenvalues();
  return largest_first(e);
}

std::array<double, 3> closed_form_principal_stresses(const StressVector& s) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor(s), Eigen::EigenvaluesOnly);
  return largest_first(solver.eigenvalues());
}

double tresca(const StressVector& s) {
  const auto p = principal_stresses(s);
  return 0.5 * (p[0] - p[2]);
}

}  // namespace coatfft
