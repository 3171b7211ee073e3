#pragma once
// The remainder of the split kernel (docs/theory.md 4.5): R(k) = H(k) - Cinf/k - A exp(-beta k)/k,
// its tabulation, the scan of the FRF's length scales that chooses beta and the cut-off beyond
// which R is negligible, and the window that splits R into a long and a short range part.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "convolution/kernels/detail/ewald_window.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"

namespace coatfft::detail::split {

using std::numbers::pi;
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// The remainder R(k) = H(k) - Cinf/k - A exp(-beta k)/k of the split, A = C0 - Cinf: bounded at
// k = 0 (H = C0/k + O(1)) and decaying like max(exp(-beta k), |k H - Cinf|)/k.
class Remainder {
 public:
  Remainder() = default;
  Remainder(const Frf& frf, double c_inf, double A, double beta)
      : frf_(&frf), c_inf_(c_inf), A_(A), beta_(beta) {}

  // k H(k) - Cinf (dimension of C), checked: for the searches that need one k at a time.
  double q(double k) const { return checked_q(k, (*frf_)(k)); }
  // q at every k of `k` into `out` (same size): one Frf::evaluate batch, each value checked as
  // q(k) checks it. Every sampling loop goes through here, so that an FRF with a cost per call
  // (Frf::evaluate) pays it once per loop.
  void q(std::span<const double> k, std::span<double> out) const {
    if (k.empty()) return;  // no call for nothing (a call may cost)
    frf_->evaluate(k, out);
    for (std::size_t i = 0; i < k.size(); ++i) out[i] = checked_q(k[i], out[i]);
  }
  double exponential(double k) const { return A_ == 0.0 ? 0.0 : A_ * std::exp(-beta_ * k); }
  // The exact R at every k > 0 of `k` into `out`, one batch.
  void exact(std::span<const double> k, std::span<double> out) const {
    q(k, out);
    for (std::size_t i = 0; i < k.size(); ++i) out[i] = (out[i] - exponential(k[i])) / k[i];
  }

  // Tabulates R on [k_lo, k_hi], log-spaced; beyond k_hi k H - Cinf is negligible, below k_lo R
  // is constant to the table's accuracy.
  void tabulate(double k_lo, double k_hi, int per_decade) {
    u0_ = std::log(k_lo);
    du_ = std::log(10.0) / per_decade;
    const auto n = static_cast<std::ptrdiff_t>(std::ceil((std::log(k_hi) - u0_) / du_)) + 1;
    table_.resize(static_cast<std::size_t>(std::max<std::ptrdiff_t>(n, 4)));
    std::vector<double> k(table_.size());
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = std::exp(u0_ + du_ * static_cast<double>(i));
    exact(k, table_);
    k_lo_ = k_lo;
    k_hi_ = std::exp(u0_ + du_ * static_cast<double>(table_.size() - 1));
  }
  double k_hi() const { return k_hi_; }

  // R(k) from the table (cubic Lagrange in log k); k = 0 gives R(0).
  double operator()(double k) const {
    if (k <= k_lo_) return table_.front();
    if (k >= k_hi_) return -exponential(k) / k;
    const double s = (std::log(k) - u0_) / du_;
    const auto last = static_cast<std::ptrdiff_t>(table_.size()) - 1;
    auto i = static_cast<std::ptrdiff_t>(s) - 1;
    i = std::clamp<std::ptrdiff_t>(i, 0, last - 3);
    const double x = s - static_cast<double>(i);  // in [0, 3] (1..2 inside the table)
    const double* f = table_.data() + i;
    // Lagrange weights for nodes 0, 1, 2, 3.
    const double w0 = -(x - 1.0) * (x - 2.0) * (x - 3.0) / 6.0;
    const double w1 = x * (x - 2.0) * (x - 3.0) / 2.0;
    const double w2 = -x * (x - 1.0) * (x - 3.0) / 2.0;
    const double w3 = x * (x - 1.0) * (x - 2.0) / 6.0;
    return w0 * f[0] + w1 * f[1] + w2 * f[2] + w3 * f[3];
  }

 private:
  double checked_q(double k, double h) const {
    COATFFT_REQUIRE(std::isfinite(h) && h > 0, "split_frf_kernel: the FRF '", frf_->name(),
                    "' gives H(", k, " rad/m) = ", h, " m/Pa, but it must be finite and > 0");
    return k * h - c_inf_;
  }

  const Frf* frf_ = nullptr;
  double c_inf_ = 0.0;
  double A_ = 0.0;
  double beta_ = 0.0;
  double u0_ = 0.0;
  double du_ = 1.0;
  double k_lo_ = 0.0;
  double k_hi_ = 0.0;
  std::vector<double> table_;
};

// What a log-spaced scan of k H(k) - Cinf tells about the FRF's length scales.
struct Scan {
  double k_lo = 0.0;  // below: R constant to ~1e-7 relative
  double k_hi = 0.0;  // above: |k H - Cinf| negligible
  double beta = 0.0;  // automatic beta
  bool remainder_zero = false;
};

// Samples k H - Cinf over the grid's length scales [l_min, l_max] (and beyond, until the FRF's
// asymptotic regimes) and reads its scales off.
Scan scan_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max);

// The smallest k above which |R(k)| k <= tol c_max (R from the table, the analytic tail beyond).
double remainder_cutoff(const Remainder& rem, double A, double beta, double tol_abs);

// The window of the split R = R w + R (1 - w), convolution/kernels/detail/ewald_window.hpp.
inline double window(double sigma, double k) {
  return detail::ewald_window(sigma, k);
}
inline double one_minus_window(double sigma, double k) {
  return detail::ewald_window_complement(sigma, k);
}

}  // namespace coatfft::detail::split
