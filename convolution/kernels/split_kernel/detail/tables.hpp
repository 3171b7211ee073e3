#pragma once
// The split kernel's tables: even and uniform tables with 6-point Lagrange interpolation, the
// Hankel table of a radial kernel, and the helpers its parts share.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "core/detail/lagrange.hpp"

namespace coatfft::detail::split {

// a[j * stride + i] = a[i * stride + j] for 0 <= i < j < n: completes a symmetric n x n array of
// which the part i >= j was computed, in 64 x 64 tiles (a plain transposed copy is cache-bound).
void fill_lower_triangle(double* a, std::ptrdiff_t n, std::ptrdiff_t stride, int threads);

// An even function f(|x|) from its values at x_i = i h, i >= 0, by 6-point Lagrange
// interpolation; lookups are valid for 0 <= x <= (size - 4) h.
class EvenTable {
 public:
  EvenTable(const std::vector<double>& values, double h) : inv_h_(1.0 / h), size_(values.size()) {
    // Two mirrored nodes in front (f is even), so that a lookup near 0 needs no index fold.
    padded_.resize(values.size() + 2);
    padded_[0] = values.size() > 2 ? values[2] : 0.0;
    padded_[1] = values.size() > 1 ? values[1] : 0.0;
    std::copy(values.begin(), values.end(), padded_.begin() + 2);
  }
  std::ptrdiff_t size() const { return static_cast<std::ptrdiff_t>(size_); }

  double operator()(double x) const {
    const double s = x * inv_h_;  // a multiplication: the long part makes ~1.4 M lookups
    const auto i0 = static_cast<std::ptrdiff_t>(s);
    // Nodes i0 - 2 .. i0 + 3; node i0 - 2 is padded_[i0].
    return detail::lagrange6(padded_.data() + i0, s - static_cast<double>(i0));
  }

 private:
  double inv_h_;
  std::size_t size_;
  std::vector<double> padded_;
};

// Radial kernel g(r) = (1/2 pi) int_0^kc f(k) J0(k r) k dk = sum_j kw_j J0(kn_j r) on the uniform
// table r_i = i dr up to r_max (g is even in r and smooth on the scale 1/kc).
// J0 itself comes from a table at step 1/64 (J0 is band-limited to 1: interpolation error
// < 0.005 / 64^6 = 7e-14, far below the table's own interpolation error in r; 1.2 million
// gsl_sf_bessel_J0 calls took 0.03 s, a fifth of the kernel at 1024^2), up to arguments of 2^16
// steps (1024); beyond, gsl_sf_bessel_J0 (only the hankel route gets there).
EvenTable hankel_table(const std::vector<double>& kw, const std::vector<double>& kn, double dr,
                       double r_max, int threads);

// f on [k0, k_max] at uniform spacing dk (nodes from k0 - 2 dk, so that every lookup has a
// centred 6-point stencil), quintic Lagrange interpolation (error ~ dk^6 f^(6) / 1000); 0 beyond
// k_max. f maps the vector of nodes |k| to the values there: one batch (Frf::evaluate).
class UniformTable {
 public:
  UniformTable() = default;
  template <typename F>
  UniformTable(const F& f, double k0, double dk, double k_max)
      : k0_(k0 - 2.0 * dk), dk_(dk), k_max_(k_max) {
    const auto n = static_cast<std::ptrdiff_t>(std::ceil((k_max - k0) / dk)) + 6;
    std::vector<double> k(static_cast<std::size_t>(n));
    for (std::ptrdiff_t i = 0; i < n; ++i)
      k[static_cast<std::size_t>(i)] = std::abs(k0_ + dk * static_cast<double>(i));
    v_ = f(k);
  }
  std::ptrdiff_t size() const { return static_cast<std::ptrdiff_t>(v_.size()); }
  double operator()(double k) const {
    if (k >= k_max_) return 0.0;
    const double s = (k - k0_) / dk_;
    auto i = static_cast<std::ptrdiff_t>(s) - 2;
    i = std::clamp<std::ptrdiff_t>(i, 0, size() - 6);
    return detail::lagrange6(v_.data() + i, s - static_cast<double>(i + 2));
  }

 private:
  double k0_ = 0.0;
  double dk_ = 1.0;
  double k_max_ = 0.0;
  std::vector<double> v_;
};

// sin(pi x) / (pi x).
inline double sinc_pi(double x) {
  if (x == 0.0) return 1.0;
  return std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
}

// Scratch memory shared by the long part's point values and the short part's fold (used one
// after the other): first touches of fresh memory cost ~0.6 ms per MiB on the development VM.
inline double* scratch(std::vector<double>& spare, std::ptrdiff_t n) {
  if (spare.size() < static_cast<std::size_t>(n)) spare.resize(static_cast<std::size_t>(n));
  return spare.data();
}

}  // namespace coatfft::detail::split
