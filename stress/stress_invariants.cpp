#include "stress/stress_invariants.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "stress/detail/principal_closed_form.hpp"

namespace coatfft {

namespace {

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

// The power of two that brings s's largest component near 1 where it lies outside [1e-90,
// 1e90] Pa: the squares and cubes of the closed forms overflow or underflow beyond. 0 within, and
// for a tensor of zeros or with a NaN or an infinity (passed on as they are). Scaling by a power
// of two is exact, so the scaled tensor gives the unscaled formulas' values.
int extreme_exponent(const StressVector& s) {
  double scale = 0.0;
  bool finite = true;
  for (const double v : s) {
    scale = std::max(scale, std::abs(v));
    finite = finite && std::isfinite(v);
  }
  if (!finite || detail::in_closed_form_range(scale)) return 0;
  int exponent = 0;
  std::frexp(scale, &exponent);
  return exponent;
}

StressVector scaled(const StressVector& s, int exponent) {
  StressVector t;
  for (std::size_t i = 0; i < s.size(); ++i) t[i] = std::ldexp(s[i], -exponent);
  return t;
}

}  // namespace

double von_mises(const StressVector& s) {
  const int exponent = extreme_exponent(s);
  const StressVector& t = exponent == 0 ? s : scaled(s, exponent);
  return std::ldexp(detail::von_mises_unscaled(t[0], t[1], t[2], t[3], t[4], t[5]), exponent);
}

std::array<double, 3> principal_stresses(const StressVector& s) {
  const Eigen::Vector3d e =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor(s), Eigen::EigenvaluesOnly)
          .eigenvalues();
  return largest_first(e);
}

std::array<double, 3> closed_form_principal_stresses(const StressVector& s) {
  const int exponent = extreme_exponent(s);
  const StressVector& t = exponent == 0 ? s : scaled(s, exponent);
  std::array<double, 3> p = detail::principal_closed_form(t[0], t[1], t[2], t[3], t[4], t[5]);
  for (double& v : p) v = std::ldexp(v, exponent);
  return p;
}

double tresca(const StressVector& s) {
  const auto p = principal_stresses(s);
  return 0.5 * (p[0] - p[2]);
}

}  // namespace coatfft
