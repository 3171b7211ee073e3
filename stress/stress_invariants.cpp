#include "stress/stress_invariants.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace coatfft {

double von_mises(const StressVector& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

std::array<double, 3> principal_stresses(const StressVector& s) {
  Eigen::Matrix3d m;
  m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
  // The symmetric solver's eigenvalues come sorted increasingly.
  const Eigen::Vector3d e =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  return {e[2], e[1], e[0]};
}

double tresca(const StressVector& s) {
  const auto p = principal_stresses(s);
  return 0.5 * (p[0] - p[2]);
}

}  // namespace coatfft
