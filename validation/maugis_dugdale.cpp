#include "validation/maugis_dugdale.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace coatfft {

MaugisDugdale::MaugisDugdale(double radius, double plane_strain_modulus, double work_of_adhesion,
                             double range)
    : radius_(radius), modulus_(plane_strain_modulus), work_(work_of_adhesion), range_(range) {
  COATFFT_REQUIRE(radius > 0 && plane_strain_modulus > 0 && work_of_adhesion > 0 && range > 0,
                  "MaugisDugdale: radius, modulus, work of adhesion and range must be > 0");
  constexpr double pi = std::numbers::pi;
  k_ = 4.0 * modulus_ / 3.0;
  const double sigma0 = work_ / range_;
  lambda_ = 2.0 * sigma0 * std::cbrt(radius_ / (pi * work_ * k_ * k_));
  a_scale_ = std::cbrt(pi * work_ * radius_ * radius_ / k_);
  p_scale_ = pi * work_ * radius_;
  d_scale_ = std::cbrt(pi * pi * work_ * work_ * radius_ / (k_ * k_));
}

MaugisDugdalePoint MaugisDugdale::at(double m) const {
  COATFFT_REQUIRE(m > 1, "MaugisDugdale: m = ", m, " must exceed 1");
  const double x = std::sqrt(m * m - 1.0), t = std::atan(x), l = lambda_;
  // The first equation is a quadratic in A: alpha A^2 + beta A - 1 = 0, its positive root.
  const double alpha = 0.5 * l * (x + (m * m - 2.0) * t);
  const double beta = 4.0 * l * l / 3.0 * (x * t - m + 1.0);
  const double A = 2.0 / (beta + std::sqrt(beta * beta + 4.0 * alpha));
  const double p = A * A * A - l * A * A * (x + m * m * t);
  const double d = A * A - 4.0 / 3.0 * A * l * x;
  return {m, A * a_scale_, m * A * a_scale_, p * p_scale_, d * d_scale_};
}

std::vector<MaugisDugdalePoint> MaugisDugdale::curve(double m_max, int count) const {
  std::vector<MaugisDugdalePoint> points;
  const double first = 1e-6, last = m_max - 1.0;
  for (int k = 0; k < count; ++k)
    points.push_back(at(1.0 + first * std::pow(last / first, k / (count - 1.0))));
  return points;
}

double MaugisDugdale::pull_off_load() const {
  // The load along the curve falls from the large-contact end to its minimum and rises beyond:
  // scan in log(m - 1), then refine the bracket by golden sections.
  const auto load = [&](double s) { return at(1.0 + std::exp(s)).load; };
  double lo = std::log(1e-8), hi = std::log(1e4);
  const int scan = 400;
  int best = 0;
  double best_load = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= scan; ++k) {
    const double l = load(lo + (hi - lo) * k / scan);
    if (l < best_load) best_load = l, best = k;
  }
  double a = lo + (hi - lo) * std::max(best - 1, 0) / scan;
  double b = lo + (hi - lo) * std::min(best + 1, scan) / scan;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 200; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    (load(c) < load(d) ? b : a) = load(c) < load(d) ? d : c;
  }
  return load(0.5 * (a + b));
}

double MaugisDugdale::load_at_approach(double delta) const {
  // Along growing m the approach first falls (the contact shrinks) and, past the jump-off point
  // of large lambda, turns; the branch of the largest contact is the part before the turn.
  const auto point = [&](double s) { return at(1.0 + std::exp(s)); };
  double lo = std::log(1e-10), hi = std::log(1e4);
  // The turn: the smallest approach along the curve (the branch's end).
  const int scan = 800;
  int turn = scan;
  double smallest = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= scan; ++k) {
    const double d = point(lo + (hi - lo) * k / scan).approach;
    if (d < smallest) smallest = d, turn = k;
  }
  hi = lo + (hi - lo) * turn / scan;
  if (delta < point(hi).approach || delta > point(lo).approach)
    return std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 200; ++k) {  // the approach falls monotonically on [lo, hi]
    const double mid = 0.5 * (lo + hi);
    (point(mid).approach > delta ? lo : hi) = mid;
  }
  return point(0.5 * (lo + hi)).load;
}

}  // namespace coatfft
