#include "convolution/kernels/split_kernel/detail/remainder.hpp"

namespace coatfft::detail::split {
namespace {

// k H(k) - Cinf at log-spaced k (8 per decade), from where k H is C0 to where it is Cinf.
struct FrfSamples {
  std::vector<double> k;
  std::vector<double> q;
  double q_max = 0.0;
};

FrfSamples sample_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max) {
  const double tol_q = 64.0 * kEpsilon * c_max;
  double k_a = 1e-6 / l_max;
  double k_b = 1e6 / l_min;
  // Extend until the ends are in the asymptotic regimes (k H -> C0 below, -> Cinf above).
  for (int it = 0; it < 6 && std::abs(rem.q(k_a) - A) > 1e-9 * c_max; ++it) k_a *= 1e-3;
  for (int it = 0; it < 6 && std::abs(rem.q(k_b)) > tol_q; ++it) k_b *= 1e3;
  constexpr int per_decade = 8;
  const auto n = static_cast<int>(std::ceil(std::log10(k_b / k_a) * per_decade)) + 1;
  FrfSamples s;
  s.k.resize(static_cast<std::size_t>(n));
  s.q.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < s.k.size(); ++i)
    s.k[i] = k_a * std::pow(10.0, static_cast<double>(i) / per_decade);
  rem.q(s.k, s.q);
  for (const double qi : s.q) s.q_max = std::max(s.q_max, std::abs(qi));
  return s;
}

// beta: the exponential with the same first moment, int_0^inf (k H - Cinf) dk = A / beta
// (trapezoid in log k; accuracy is irrelevant, any beta > 0 is exact, a good one keeps R small).
// When k H overshoots the range [Cinf, C0] (e.g. a soft interlayer under a stiff top) the moment
// is dominated by the overshoot; then beta = ln 2 / k_t at the last (largest-k) half-way
// crossing, which follows the top layer. `last`: the last sample above rounding.
double automatic_beta(const FrfSamples& s, double A, std::size_t last) {
  const std::vector<double>& k = s.k;
  const std::vector<double>& q = s.q;
  double m1 = A * k[0];
  for (std::size_t b = 1; b < k.size(); ++b) {
    const std::size_t a = b - 1;
    m1 += 0.5 * (q[a] * k[a] + q[b] * k[b]) * std::log(k[b] / k[a]);
  }
  bool overshoot = false;
  for (const double qi : q) {
    const double f = qi / A;  // 1 at k = 0, 0 at infinity
    if (f > 1.05 || f < -0.05) overshoot = true;
  }
  if (!overshoot && m1 / A > 0 && std::isfinite(m1)) return A / m1;
  double kt = k[last];
  for (std::size_t i = k.size(); i-- > 0;)
    if (q[i] / A > 0.5) {
      kt = k[i];
      break;
    }
  return std::log(2.0) / kt;
}

}  // namespace

Scan scan_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max) {
  const FrfSamples s = sample_frf(rem, A, c_max, l_min, l_max);
  const std::size_t n = s.k.size();
  const double tol_q = 64.0 * kEpsilon * c_max;
  Scan scan;
  scan.remainder_zero = A == 0.0 && s.q_max <= tol_q;
  // k_hi: a decade past the last wavenumber where k H - Cinf is above rounding.
  std::size_t last = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(s.q[i]) > tol_q) last = i;
  scan.k_hi = 10.0 * s.k[last];
  // k_lo: a decade below the first wavenumber where k H departs from C0 by 1e-7 of its range.
  const double range = std::max(s.q_max, std::abs(A));
  std::size_t first = n - 1;
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(s.q[i] - A) > 1e-7 * range) {
      first = i;
      break;
    }
  scan.k_lo = std::min(0.1 * s.k[first], 0.01 * scan.k_hi);
  if (A != 0.0) scan.beta = automatic_beta(s, A, last);
  return scan;
}

double remainder_cutoff(const Remainder& rem, double A, double beta, double tol_abs) {
  double k_cut = 0.0;
  if (A != 0.0 && std::abs(A) > tol_abs) k_cut = std::log(std::abs(A) / tol_abs) / beta;
  k_cut = std::min(k_cut, 1e300);
  // Scan the tabulated part downwards from k_hi.
  const double k_hi = rem.k_hi();
  constexpr int per_decade = 64;
  for (int i = 0; i < 40 * per_decade; ++i) {
    const double k = k_hi * std::pow(10.0, -static_cast<double>(i) / per_decade);
    if (std::abs(rem(k)) * k > tol_abs) {
      k_cut = std::max(k_cut, k * std::pow(10.0, 1.0 / per_decade));
      break;
    }
  }
  return k_cut;
}

}  // namespace coatfft::detail::split
