#include "convolution/split_frf_kernel.hpp"

#include <fftw3.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <utility>
#include <vector>

#include "convolution/cell_average_stencil.hpp"
#include "convolution/fftw_plan.hpp"
#include "convolution/love_influence.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace detail {

namespace {

// F(X, Y) of split_rectangle_integral; odd in X and in Y, F(0, Y) = F(X, 0) = 0.
double corner_beta(double X, double Y, double beta) {
  if (X == 0.0 || Y == 0.0) return 0.0;
  const double X2 = X * X;
  const double Y2 = Y * Y;
  const double b2 = beta * beta;
  return X * std::asinh(Y / std::sqrt(X2 + b2)) + Y * std::asinh(X / std::sqrt(Y2 + b2)) -
         beta * std::atan(X * Y / (beta * std::sqrt(X2 + Y2 + b2)));
}

}  // namespace

double split_rectangle_integral(double x, double y, double dx, double dy, double beta) {
  COATFFT_REQUIRE(std::isfinite(beta) && beta > 0, "split_rectangle_integral: beta = ", beta,
                  " m, but beta must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0,
                  "split_rectangle_integral: cell (", dx, ", ", dy, ") m must be finite and > 0");
  const double a = 0.5 * dx;
  const double b = 0.5 * dy;
  return corner_beta(x + a, y + b, beta) - corner_beta(x + a, y - b, beta) -
         corner_beta(x - a, y + b, beta) + corner_beta(x - a, y - b, beta);
}

}  // namespace detail

namespace {

constexpr double pi = std::numbers::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();

// Gauss-Legendre nodes and weights on [-1, 1]: Newton's iteration on P_n from the asymptotic
// initial guess (Numerical Recipes' gauleg), accurate to a few ulps for the n <= 16 used here.
void gauss_legendre(int n, std::vector<double>& t, std::vector<double>& w) {
  t.assign(static_cast<std::size_t>(n), 0.0);
  w.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0;
      double p1 = x;
      for (int j = 2; j <= n; ++j) {
        const double p2 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    t[static_cast<std::size_t>(i)] = -x;
    w[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

// The remainder R(k) = H(k) - Cinf/k - A exp(-beta k)/k of the split, A = C0 - Cinf: bounded at
// k = 0 (H = C0/k + O(1)) and decaying like max(exp(-beta k), |k H - Cinf|)/k.
class Remainder {
 public:
  Remainder(const Frf& frf, double c_inf, double A, double beta)
      : frf_(frf), c_inf_(c_inf), A_(A), beta_(beta) {}

  // k H(k) - Cinf (dimension of C), checked.
  double q(double k) const {
    const double h = frf_(k);
    COATFFT_REQUIRE(std::isfinite(h) && h > 0, "split_frf_kernel: the FRF '", frf_.name(),
                    "' gives H(", k, " rad/m) = ", h, " m/Pa, but it must be finite and > 0");
    return k * h - c_inf_;
  }
  double exponential(double k) const { return A_ == 0.0 ? 0.0 : A_ * std::exp(-beta_ * k); }
  double exact(double k) const { return (q(k) - exponential(k)) / k; }

  // Tabulates R on [k_lo, k_hi], log-spaced; beyond k_hi k H - Cinf is negligible, below k_lo R
  // is constant to the table's accuracy.
  void tabulate(double k_lo, double k_hi, int per_decade) {
    u0_ = std::log(k_lo);
    du_ = std::log(10.0) / per_decade;
    const auto n = static_cast<std::ptrdiff_t>(std::ceil((std::log(k_hi) - u0_) / du_)) + 1;
    table_.resize(static_cast<std::size_t>(std::max<std::ptrdiff_t>(n, 4)));
    for (std::size_t i = 0; i < table_.size(); ++i)
      table_[i] = exact(std::exp(u0_ + du_ * static_cast<double>(i)));
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
  const Frf& frf_;
  double c_inf_;
  double A_;
  double beta_;
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

Scan scan_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max) {
  Scan s;
  const double tol_q = 64.0 * eps * c_max;
  double k_a = 1e-6 / l_max;
  double k_b = 1e6 / l_min;
  // Extend until the ends are in the asymptotic regimes (k H -> C0 below, -> Cinf above).
  for (int it = 0; it < 6 && std::abs(rem.q(k_a) - A) > 1e-9 * c_max; ++it) k_a *= 1e-3;
  for (int it = 0; it < 6 && std::abs(rem.q(k_b)) > tol_q; ++it) k_b *= 1e3;
  constexpr int per_decade = 8;
  const auto n = static_cast<int>(std::ceil(std::log10(k_b / k_a) * per_decade)) + 1;
  std::vector<double> k(static_cast<std::size_t>(n));
  std::vector<double> q(static_cast<std::size_t>(n));
  double q_max = 0.0;
  for (int i = 0; i < n; ++i) {
    k[static_cast<std::size_t>(i)] = k_a * std::pow(10.0, static_cast<double>(i) / per_decade);
    q[static_cast<std::size_t>(i)] = rem.q(k[static_cast<std::size_t>(i)]);
    q_max = std::max(q_max, std::abs(q[static_cast<std::size_t>(i)]));
  }
  s.remainder_zero = A == 0.0 && q_max <= tol_q;
  // k_hi: a decade past the last wavenumber where k H - Cinf is above rounding.
  int last = 0;
  for (int i = 0; i < n; ++i)
    if (std::abs(q[static_cast<std::size_t>(i)]) > tol_q) last = i;
  s.k_hi = 10.0 * k[static_cast<std::size_t>(last)];
  // k_lo: a decade below the first wavenumber where k H departs from C0 by 1e-7 of its range.
  const double range = std::max(q_max, std::abs(A));
  int first = n - 1;
  for (int i = n - 1; i >= 0; --i)
    if (std::abs(q[static_cast<std::size_t>(i)] - A) > 1e-7 * range) first = i;
  s.k_lo = 0.1 * k[static_cast<std::size_t>(first)];
  s.k_lo = std::min(s.k_lo, 0.01 * s.k_hi);
  if (A != 0.0) {
    // beta: the exponential with the same first moment, int_0^inf (k H - Cinf) dk = A / beta
    // (trapezoid in log k; accuracy is irrelevant, any beta > 0 is exact, a good one keeps R
    // small). When k H overshoots the range [Cinf, C0] (e.g. a soft interlayer under a stiff top)
    // the moment is dominated by the overshoot; then beta = ln 2 / k_t at the last (largest-k)
    // half-way crossing, which follows the top layer.
    double m1 = A * k[0];
    bool overshoot = false;
    for (int i = 1; i < n; ++i) {
      const auto a = static_cast<std::size_t>(i - 1);
      const auto b = static_cast<std::size_t>(i);
      m1 += 0.5 * (q[a] * k[a] + q[b] * k[b]) * std::log(k[b] / k[a]);
    }
    for (int i = 0; i < n; ++i) {
      const double f = q[static_cast<std::size_t>(i)] / A;  // 1 at k = 0, 0 at infinity
      if (f > 1.05 || f < -0.05) overshoot = true;
    }
    if (!overshoot && m1 / A > 0 && std::isfinite(m1)) {
      s.beta = A / m1;
    } else {
      double kt = k[static_cast<std::size_t>(last)];
      for (int i = n - 1; i >= 0; --i)
        if (q[static_cast<std::size_t>(i)] / A > 0.5) {
          kt = k[static_cast<std::size_t>(i)];
          break;
        }
      s.beta = std::log(2.0) / kt;
    }
  }
  return s;
}

// The smallest k above which |R(k)| k <= tol c_max (R from the table, the analytic tail beyond).
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

// Runs body(i) for i in [0, n) on `threads` threads (interleaved: i = w, w + t, ..., which
// balances triangular and disk-shaped loops; the bodies write disjoint outputs).
template <typename Body>
void parallel_for(std::ptrdiff_t n, int threads, const Body& body) {
  const auto t = static_cast<std::ptrdiff_t>(
      std::max(1, std::min<int>(threads, static_cast<int>(std::min<std::ptrdiff_t>(n, 1024)))));
  if (t <= 1) {
    for (std::ptrdiff_t i = 0; i < n; ++i) body(i);
    return;
  }
  std::vector<std::thread> pool;
  for (std::ptrdiff_t w = 0; w < t; ++w)
    pool.emplace_back([&, w] {
      for (std::ptrdiff_t i = w; i < n; i += t) body(i);
    });
  for (std::thread& th : pool) th.join();
}

// a[j * stride + i] = a[i * stride + j] for 0 <= i < j < n: completes a symmetric n x n array of
// which the part i >= j was computed, in 64 x 64 tiles (a plain transposed copy is cache-bound).
void fill_lower_triangle(double* a, std::ptrdiff_t n, std::ptrdiff_t stride, int threads) {
  constexpr std::ptrdiff_t tile = 64;
  parallel_for((n + tile - 1) / tile, threads, [&](std::ptrdiff_t tj) {
    const std::ptrdiff_t j_end = std::min(n, (tj + 1) * tile);
    for (std::ptrdiff_t ti = 0; ti <= tj * tile; ti += tile)
      for (std::ptrdiff_t j = tj * tile; j < j_end; ++j)
        for (std::ptrdiff_t i = ti; i < std::min(j, ti + tile); ++i)
          a[j * stride + i] = a[i * stride + j];
  });
}

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

  // 6-point Lagrange on the nodes i0 - 2 .. i0 + 3 around x = (i0 + t) h, with the weights in
  // product form (prefix and suffix products of X - j, X = t + 2, and the constants 1/(prod of
  // node differences)): ~20 multiplications and no division, against 30 divisions for the
  // generic loop this replaced. Error ~0.005 (h w)^6 for a function band-limited to w.
  double operator()(double x) const {
    const double s = x * inv_h_;  // a multiplication: the long part makes ~1.4 M lookups
    const auto i0 = static_cast<std::ptrdiff_t>(s);
    const double t = s - static_cast<double>(i0);  // in [0, 1)
    const double* f = padded_.data() + i0;         // node i0 - 2 is padded_[i0]
    const double m0 = t + 2.0, m1 = t + 1.0, m2 = t, m3 = t - 1.0, m4 = t - 2.0, m5 = t - 3.0;
    const double p01 = m0 * m1, p012 = p01 * m2, p0123 = p012 * m3, p01234 = p0123 * m4;
    const double s45 = m4 * m5, s345 = m3 * s45, s2345 = m2 * s345, s12345 = m1 * s2345;
    return (-f[0] * s12345 + f[5] * p01234) * (1.0 / 120.0) +
           (f[1] * m0 * s2345 - f[4] * p0123 * m5) * (1.0 / 24.0) +
           (-f[2] * p01 * s345 + f[3] * p012 * s45) * (1.0 / 12.0);
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
                       double r_max, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(std::ceil(r_max / dr)) + 4;
  const double x_max = (kn.empty() ? 0.0 : kn.back()) * dr * static_cast<double>(n);
  constexpr double h = 1.0 / 64.0;
  const auto nj = static_cast<std::ptrdiff_t>(std::min(std::ceil(x_max / h), 65536.0)) + 4;
  std::vector<double> j0(static_cast<std::size_t>(nj));
  parallel_for(nj, threads, [&](std::ptrdiff_t i) {
    j0[static_cast<std::size_t>(i)] = gsl_sf_bessel_J0(h * static_cast<double>(i));
  });
  const EvenTable bessel(j0, h);
  const double x_table = h * static_cast<double>(nj - 4);
  std::vector<double> g(static_cast<std::size_t>(n));
  parallel_for(n, threads, [&](std::ptrdiff_t i) {
    const double r = dr * static_cast<double>(i);
    double sum = 0.0;
    for (std::size_t j = 0; j < kn.size(); ++j) {
      const double x = kn[j] * r;
      sum += kw[j] * (x <= x_table ? bessel(x) : gsl_sf_bessel_J0(x));
    }
    g[static_cast<std::size_t>(i)] = sum;
  });
  return EvenTable(g, dr);
}

// f on [k0, k_max] at uniform spacing dk (nodes from k0 - 2 dk, so that every lookup has a
// centred 6-point stencil), quintic Lagrange interpolation; 0 beyond k_max.
class UniformTable {
 public:
  UniformTable() = default;
  template <typename F>
  UniformTable(const F& f, double k0, double dk, double k_max)
      : k0_(k0 - 2.0 * dk), dk_(dk), k_max_(k_max) {
    const auto n = static_cast<std::ptrdiff_t>(std::ceil((k_max - k0) / dk)) + 6;
    v_.resize(static_cast<std::size_t>(n));
    for (std::ptrdiff_t i = 0; i < n; ++i)
      v_[static_cast<std::size_t>(i)] = f(std::abs(k0_ + dk * static_cast<double>(i)));
  }
  std::ptrdiff_t size() const { return static_cast<std::ptrdiff_t>(v_.size()); }
  double operator()(double k) const {
    if (k >= k_max_) return 0.0;
    // 6-point Lagrange (quintic): error ~ dk^6 f^(6) / 1000.
    const double s = (k - k0_) / dk_;
    auto i = static_cast<std::ptrdiff_t>(s) - 2;
    i = std::clamp<std::ptrdiff_t>(i, 0, size() - 6);
    const double x = s - static_cast<double>(i);
    const double* f = v_.data() + i;
    const double x0 = x, x1 = x - 1.0, x2 = x - 2.0, x3 = x - 3.0, x4 = x - 4.0, x5 = x - 5.0;
    return -f[0] * x1 * x2 * x3 * x4 * x5 / 120.0 + f[1] * x0 * x2 * x3 * x4 * x5 / 24.0 -
           f[2] * x0 * x1 * x3 * x4 * x5 / 12.0 + f[3] * x0 * x1 * x2 * x4 * x5 / 12.0 -
           f[4] * x0 * x1 * x2 * x3 * x5 / 24.0 + f[5] * x0 * x1 * x2 * x3 * x4 / 120.0;
  }

 private:
  double k0_ = 0.0;
  double dk_ = 1.0;
  double k_max_ = 0.0;
  std::vector<double> v_;
};

// sin(pi x) / (pi x).
double sinc_pi(double x) {
  if (x == 0.0) return 1.0;
  return std::sin(pi * x) / (pi * x);
}

}  // namespace

EvenInfluenceKernel split_frf_kernel_quarter(const Grid& grid, const Frf& frf,
                                             const SplitKernelOptions& options,
                                             SplitKernelReport* report) {
  const auto t_start = std::chrono::steady_clock::now();
  const auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  COATFFT_REQUIRE(std::isfinite(options.beta) && options.beta >= 0,
                  "split_frf_kernel: beta = ", options.beta,
                  " m, but beta must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(std::isfinite(options.sigma) && options.sigma >= 0,
                  "split_frf_kernel: sigma = ", options.sigma,
                  " m, but sigma must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(options.tolerance > 0 && options.tolerance <= 1e-3,
                  "split_frf_kernel: tolerance = ", options.tolerance,
                  ", but it must be in (0, 1e-3]");
  COATFFT_REQUIRE(options.threads >= 1 && options.threads <= 1024,
                  "split_frf_kernel: threads = ", options.threads, ", but it must be in [1, 1024]");
  const int threads = options.threads;
  COATFFT_REQUIRE(options.max_alias_order >= 0 && options.max_alias_order <= 4096,
                  "split_frf_kernel: max_alias_order = ", options.max_alias_order,
                  ", but it must be in [0, 4096]");
  const double c0 = frf.c0();
  const double c_inf = frf.c_inf();
  COATFFT_REQUIRE(std::isfinite(c0) && c0 > 0, "split_frf_kernel: c0 = ", c0, " 1/Pa of FRF '",
                  frf.name(), "', but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(c_inf) && c_inf > 0, "split_frf_kernel: c_inf = ", c_inf,
                  " 1/Pa of FRF '", frf.name(), "', but it must be finite and > 0");

  SplitKernelReport rep;
  rep.c0 = c0;
  rep.c_inf = c_inf;
  const std::ptrdiff_t nx = grid.nx();
  const std::ptrdiff_t ny = grid.ny();
  const double dx = grid.dx();
  const double dy = grid.dy();
  const double d_max = std::max(dx, dy);
  const double c_max = std::max(c0, c_inf);
  const double A = c0 - c_inf;

  Remainder probe(frf, c_inf, A, 1.0);
  const Scan scan = scan_frf(probe, A, c_max, std::min(dx, dy), std::max(grid.lx(), grid.ly()));
  const double beta = A == 0.0 ? 0.0 : (options.beta > 0 ? options.beta : scan.beta);
  rep.beta = beta;
  rep.remainder_zero = scan.remainder_zero;

  // (a) Cinf/k <-> Cinf/(2 pi r): Love's coefficients for E* = 2/Cinf (theory.md 1.5), computed
  // as love_kernel does (love_influence / E*) near the origin.
  // (b) A exp(-beta k)/k <-> A/(2 pi sqrt(r^2 + beta^2)): split_rectangle_integral near the origin.
  // Far from the cell (r >= 32 d) both kernels are analytic over it and the 4-corner sums cancel
  // (log10((r/d)^2) digits lost), so both are integrated there by one n x n Gauss-Legendre rule,
  // which converges like rho^(-2n), rho ~ 4 r/d (Bernstein ellipse of the nearest singularity):
  // n = 4 from 32 d, 3 from 64 d (rho^-6 < 4e-15), 2 from 512 d (rho^-4 < 6e-14 of a coefficient
  // 512x smaller than K(0,0)); coarser than love_influence's rules (exact to rounding, docs in
  // love_influence.cpp), by the tolerance of this kernel.
  const double love_E_star = 2.0 / c_inf;
  // The kernel is even in x and y: only its quarter di, dj >= 0 is computed and returned
  // (EvenInfluenceKernel; DcfftOperator transforms it directly, and the (2nx, 2ny) wrap-around
  // array, 32 MiB at 1024^2, is never formed). First touches of fresh memory cost ~0.6 ms per
  // MiB on the development VM, so the long part's point values and the short part's fold share
  // one scratch buffer (they are used one after the other).
  Field quarter_field(nx + 1, ny + 1);
  const auto quarter = [&](std::ptrdiff_t i, std::ptrdiff_t j) -> double& {
    return quarter_field(i, j);
  };
  std::vector<double> spare;
  const auto scratch = [&](std::ptrdiff_t n) -> double* {
    if (spare.size() < static_cast<std::size_t>(n)) spare.resize(static_cast<std::size_t>(n));
    return spare.data();
  };
  const double near_r = 32.0 * d_max;  // closed forms inside, smooth over a cell outside
  // Squared distances decide the rules (hypot per cell was 6 % of the kernel's time).
  const auto r_squared = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    const double x = static_cast<double>(i) * dx;
    const double y = static_cast<double>(j) * dy;
    return x * x + y * y;
  };
  const auto is_near = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    return r_squared(i, j) < near_r * near_r;
  };
  // Assigns quarter = (a) + (b) everywhere, or only at the near cells (r < 32 d) when
  // `leave_far` (the stencil pass of the long part assigns the far cells).
  const auto love_and_exponential = [&](bool leave_far) {
    std::array<std::vector<double>, 5> gt;
    std::array<std::vector<double>, 5> gw;
    for (int n = 2; n <= 4; ++n)
      gauss_legendre(n, gt[static_cast<std::size_t>(n)], gw[static_cast<std::size_t>(n)]);
    const double ca = 0.25 * dx * dy * c_inf / (2.0 * pi);
    const double cb = 0.25 * dx * dy * A / (2.0 * pi);
    const double b2 = beta * beta;
    parallel_for(ny, threads, [&](std::ptrdiff_t j) {
      const double y = static_cast<double>(j) * dy;
      for (std::ptrdiff_t i = 0; i < nx; ++i) {
        const double x = static_cast<double>(i) * dx;
        const double r2c = r_squared(i, j);
        if (leave_far && r2c >= near_r * near_r) break;
        if (r2c < near_r * near_r) {
          double v = love_influence(x, y, dx, dy) / love_E_star;
          if (A != 0.0) v += A / (2.0 * pi) * detail::split_rectangle_integral(x, y, dx, dy, beta);
          quarter(i, j) = v;
          continue;
        }
        const auto n = static_cast<std::size_t>(r2c >= (512.0 * d_max) * (512.0 * d_max) ? 2
                                                : r2c >= (64.0 * d_max) * (64.0 * d_max) ? 3
                                                                                         : 4);
        const std::vector<double>& t = gt[n];
        const std::vector<double>& w = gw[n];
        double sum = 0.0;
        for (std::size_t a = 0; a < n; ++a) {
          const double ex = x - 0.5 * dx * t[a];
          double row = 0.0;
          for (std::size_t b = 0; b < n; ++b) {
            const double ey = y - 0.5 * dy * t[b];
            const double r2 = ex * ex + ey * ey;
            double f = ca / std::sqrt(r2);
            if (A != 0.0) f += cb / std::sqrt(r2 + b2);
            row += w[b] * f;
          }
          sum += w[a] * row;
        }
        quarter(i, j) = sum;
      }
    });
  };
  bool ab_done = false;

  if (!scan.remainder_zero) {
    Remainder rem(frf, c_inf, A, beta);
    rem.tabulate(scan.k_lo, std::max(scan.k_hi, A != 0.0 ? 50.0 / beta : 0.0), 400);
    const double tol_abs = options.tolerance * c_max;
    const double k_r = remainder_cutoff(rem, A, beta, tol_abs);  // R negligible beyond

    // The window length sigma splitting R between the Hankel (long-range) and lattice parts.
    double sigma = options.sigma > 0 ? options.sigma
                                     : std::max(std::min(grid.lx(), grid.ly()) / 32.0, 1.5 * d_max);
    if (options.route == SplitRoute::periodic) sigma = 0.0;
    if (options.route == SplitRoute::hankel) sigma = std::numeric_limits<double>::infinity();
    rep.sigma = sigma;
    // The window w = exp(-s) (1 + s + s^2/2), s = (sigma k)^2, and 1 - w = exp(-s) sum_{j>=3}
    // s^j/j! = O(k^6): the short-range part R (1 - w) then has the far field (sigma^6/6) (-lap)^3
    // of R's r^-3 tail, 1837 (sigma/r)^6 of it, so its periodic images (>= 32 sigma away) are
    // negligible (a plain Gaussian, 1 - w = O(k^2), leaves 9 (sigma/r)^2: 1e-2 at 32 sigma).
    const auto window = [&](double k) {
      if (sigma == 0.0) return 0.0;
      if (std::isinf(sigma)) return 1.0;
      const double s = (sigma * k) * (sigma * k);
      return std::exp(-s) * (1.0 + s * (1.0 + 0.5 * s));
    };
    const auto one_minus_window = [&](double k) {
      if (sigma == 0.0) return 1.0;
      if (std::isinf(sigma)) return 0.0;
      const double s = (sigma * k) * (sigma * k);
      if (s >= 1.0) return 1.0 - std::exp(-s) * (1.0 + s * (1.0 + 0.5 * s));
      // exp(-s) s^3/6 (1 + s/4 + s^2/20 + ...), 12 terms: converged to rounding for s < 1.
      double term = 1.0;
      double sum = 1.0;
      for (int j = 4; j < 16; ++j) {
        term *= s / j;
        sum += term;
      }
      return std::exp(-s) * s * s * s / 6.0 * sum;
    };

    // ---- Long-range part R w: Hankel table in r, Gauss-Legendre over each cell. ----
    const double log_tol = std::log(1.0 / options.tolerance);
    // w < tol beyond k_c: exp(-s) s^2/2 < tol at s = log_tol + 2 log(log_tol) (two Newton-free
    // fixed-point steps suffice for the tolerances allowed).
    double s_c = log_tol;
    for (int it = 0; it < 4; ++it) s_c = log_tol + 2.0 * std::log(s_c) - std::log(2.0);
    const double k_c = std::isinf(sigma) ? k_r : std::min(k_r, std::sqrt(s_c) / sigma);
    if (sigma > 0.0 && k_c > 0.0) {
      const auto t_long = std::chrono::steady_clock::now();
      const double r_max = std::hypot(grid.lx(), grid.ly());
      // Panels: geometric (halving) from the first uniform panel down to R's smallest scale, then
      // uniform of width <= 2 pi / r_max (one J0 period at r_max) up to k_c; 16 nodes each.
      const double dk_u = std::min(4.0 * pi / r_max, k_c);
      std::vector<double> edges = {0.0};
      {
        std::vector<double> geo;
        for (double e = dk_u * 0.5; e > scan.k_lo; e *= 0.5) geo.push_back(e);
        std::reverse(geo.begin(), geo.end());
        edges.insert(edges.end(), geo.begin(), geo.end());
        const auto nu = static_cast<std::ptrdiff_t>(std::ceil(k_c / dk_u));
        for (std::ptrdiff_t i = 1; i <= nu; ++i)
          edges.push_back(k_c * static_cast<double>(i) / static_cast<double>(nu));
      }
      std::vector<double> t16;
      std::vector<double> w16;
      gauss_legendre(16, t16, w16);
      std::vector<double> kn;
      std::vector<double> kw;
      for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
        const double mid = 0.5 * (edges[e] + edges[e + 1]);
        const double half = 0.5 * (edges[e + 1] - edges[e]);
        for (std::size_t q = 0; q < t16.size(); ++q) {
          const double k = mid + half * t16[q];
          kn.push_back(k);
          kw.push_back(half * w16[q] * rem.exact(k) * window(k) * k / (2.0 * pi));
        }
      }
      // g is band-limited to k_c: 6-point interpolation with k_c dr = 0.3 is accurate to ~1e-9
      // of g's scale (checked against a table with half the step in the tests).
      const double dr = 0.5 / k_c;
      const double cost = static_cast<double>(kn.size()) * (r_max / dr);
      COATFFT_REQUIRE(cost < 4e9, "split_frf_kernel: the Hankel table would need ", cost,
                      " Bessel evaluations (a layer much thinner than the domain with the hankel "
                      "route); use SplitRoute::automatic");
      const EvenTable table = hankel_table(kw, kn, dr, r_max + 4.0 * d_max, threads);
      rep.hankel_r_points = table.size();
      rep.hankel_k_nodes = static_cast<std::ptrdiff_t>(kn.size());
      // Gauss rule per cell: the kernel is smooth on the scale ell = sqrt(log_tol)/k_c (about
      // sigma; its spectrum is cut like a Gaussian of width sqrt(2) sigma). The n-point
      // Gauss-Legendre error on a cell of side d is about c_n (d/(sqrt(2) ell))^(2n) with
      // c_2 = 2e-4, c_3 = 7e-7, c_4 = 7e-9, c_5 = 3e-11, c_6 = 2e-12: n is picked for ~1e-13
      // relative, and cells larger than 1.5 ell are subdivided.
      const double ell = std::sqrt(log_tol) / k_c;
      const int sub = static_cast<int>(std::clamp(std::ceil(d_max / (ell / 1.5)), 1.0, 64.0));
      const double ratio = ell * sub / d_max;
      const int n_gl = ratio >= 24.0   ? 2
                       : ratio >= 12.0 ? 3
                       : ratio >= 4.0  ? 4
                       : ratio >= 2.5  ? 5
                                       : 6;
      std::vector<double> tg;
      std::vector<double> wg;
      gauss_legendre(n_gl, tg, wg);
      std::vector<double> ox;
      std::vector<double> wx;
      std::vector<double> oy;
      std::vector<double> wy;
      for (int s = 0; s < sub; ++s)
        for (int q = 0; q < n_gl; ++q) {
          const double c = -0.5 + (s + 0.5) / sub;
          ox.push_back((c + 0.5 * tg[static_cast<std::size_t>(q)] / sub) * dx);
          wx.push_back(0.5 * wg[static_cast<std::size_t>(q)] / sub * dx);
          oy.push_back((c + 0.5 * tg[static_cast<std::size_t>(q)] / sub) * dy);
          wy.push_back(0.5 * wg[static_cast<std::size_t>(q)] / sub * dy);
        }
      rep.cell_rule = n_gl * sub;
      const auto gauss_cell = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
        double sum = 0.0;
        for (std::size_t a = 0; a < ox.size(); ++a) {
          const double x = static_cast<double>(i) * dx + ox[a];
          double row = 0.0;
          for (std::size_t b = 0; b < oy.size(); ++b) {
            const double y = static_cast<double>(j) * dy + oy[b];
            row += wy[b] * table(std::sqrt(x * x + y * y));
          }
          sum += wx[a] * row;
        }
        return sum;
      };
      // Stencil route, where the long kernel is smooth on >= 8 cells: one point value per cell
      // and the 9-point cell-average stencil along x and y (cell_average_stencil.hpp), whose
      // error E (k d)^10 (E = 1.06e-5) is weighted by the spectrum R w (cut at k_c = 5.6/sigma,
      // largest near 2/sigma); its error kernel is concentrated within ~sigma of the origin,
      // where the near cells (r < 32 d) keep the Gauss rule: the coefficients change by
      // < 1e-11 of K(0, 0) (docs/split_kernel.md, section 5). The far cells' (a) + (b) are smooth
      // over a cell beyond 32 d and go through the same stencil, from the point values
      // Cinf/(2 pi r) + A/(2 pi sqrt(r^2 + beta^2)) (error ~E 10! (d/r)^10 of the coefficient
      // there): one pass, one table lookup and one or two square roots per cell.
      const bool stencil = ell >= 8.0 * d_max;
      if (stencil) rep.cell_rule = 1;
      love_and_exponential(stencil);
      ab_done = true;
      if (stencil) {
        constexpr std::ptrdiff_t m = detail::cell_average_half_width;
        const auto& c = detail::cell_average_weights;
        const double fa = c_inf / (2.0 * pi) * dx * dy;
        const double fb = A / (2.0 * pi) * dx * dy;
        const double b2 = beta * beta;
        // Point values (times the cell area) at i in [0, nx + m), j in [0, ny + m); the kernel is
        // even, so negative offsets read |i|, |j|. The origin's singular terms are left out: only
        // near cells reach it. Square cells on a square grid: point(i, j) = point(j, i), only
        // i >= j is evaluated.
        const std::ptrdiff_t ex = nx + m;
        const std::ptrdiff_t ey = ny + m;
        const bool symmetric = dx == dy && nx == ny;
        double* const point = scratch(ex * ey);
        const auto at = [&](std::ptrdiff_t i, std::ptrdiff_t j) -> double& {
          return point[j * ex + i];
        };
        parallel_for(ey, threads, [&](std::ptrdiff_t j) {
          const double y2 = (static_cast<double>(j) * dy) * (static_cast<double>(j) * dy);
          for (std::ptrdiff_t i = symmetric ? j : 0; i < ex; ++i) {
            const double x = static_cast<double>(i) * dx;
            const double r2 = x * x + y2;
            const double r = std::sqrt(r2);
            double f = dx * dy * table(r);
            if (r2 > 0.0) {
              f += fa / r;
              if (A != 0.0) f += fb / std::sqrt(r2 + b2);
            }
            at(i, j) = f;
          }
        });
        if (symmetric) fill_lower_triangle(point, ey, ex, threads);
        // Stencil along x, in place (row j of `point` becomes its x average at i in [0, nx)),
        // then along y into the far cells.
        parallel_for(ey, threads, [&](std::ptrdiff_t j) {
          double* p = point + j * ex;
          std::vector<double> in(p, p + ex);
          for (std::ptrdiff_t i = 0; i < nx; ++i) {
            double v = c[0] * in[static_cast<std::size_t>(i)];
            for (std::ptrdiff_t a = 1; a <= m; ++a)
              v += c[static_cast<std::size_t>(a)] * (in[static_cast<std::size_t>(std::abs(i - a))] +
                                                     in[static_cast<std::size_t>(i + a)]);
            p[i] = v;
          }
        });
        parallel_for(ny, threads, [&](std::ptrdiff_t j) {
          std::array<const double*, 2 * m + 1> rows{};
          for (std::ptrdiff_t a = -m; a <= m; ++a)
            rows[static_cast<std::size_t>(a + m)] = point + std::abs(j + a) * ex;
          double* out = &quarter(0, j);
          std::ptrdiff_t i_far = 0;
          for (; i_far < nx && is_near(i_far, j); ++i_far) out[i_far] += gauss_cell(i_far, j);
          for (std::ptrdiff_t i = i_far; i < nx; ++i) {
            double v = c[0] * rows[m][i];
            for (std::ptrdiff_t a = 1; a <= m; ++a)
              v += c[static_cast<std::size_t>(a)] * (rows[static_cast<std::size_t>(m - a)][i] +
                                                     rows[static_cast<std::size_t>(m + a)][i]);
            out[i] = v;
          }
        });
      } else {
        parallel_for(ny, threads, [&](std::ptrdiff_t j) {
          for (std::ptrdiff_t i = 0; i < nx; ++i) quarter(i, j) += gauss_cell(i, j);
        });
      }
      rep.seconds_long = since(t_long);
    }

    // ---- Short-range part R (1 - w): periodic lattice with the aliases folded. ----
    if (!std::isinf(sigma) && k_r > 0.0) {
      if (!ab_done) {
        love_and_exponential(false);
        ab_done = true;
      }
      const auto t_short = std::chrono::steady_clock::now();
      // Half periods (in cells): the images of the short-range kernel stay >= 32 sigma away.
      const std::ptrdiff_t hx =
          std::max<std::ptrdiff_t>(nx, static_cast<std::ptrdiff_t>(std::ceil(32.0 * sigma / dx)));
      const std::ptrdiff_t hy =
          std::max<std::ptrdiff_t>(ny, static_cast<std::ptrdiff_t>(std::ceil(32.0 * sigma / dy)));
      const double k_s = k_r;
      const auto order = [&](double d) {
        const double need = std::ceil(k_s * d / (2.0 * pi) + 0.5);
        if (need > options.max_alias_order) rep.alias_capped = true;
        return static_cast<int>(std::min<double>(need, options.max_alias_order));
      };
      const int px = order(dx);
      const int py = order(dy);
      rep.alias_order = std::max(px, py);
      // R (1 - w) on a uniform k grid up to the largest folded |k| (quintic interpolation, no
      // logarithm per lookup: the fold makes ~N^2 pi P^2 lookups), refined until the midpoints
      // match the exact R to tolerance x max|R|.
      const double k_table =
          std::min(k_s, std::hypot(2.0 * pi * (px + 0.5) / dx, 2.0 * pi * (py + 0.5) / dy));
      // Two segments: [0, k1] resolves the window (scale 1/sigma), [k1, k_table] R's own decay;
      // one table at the finer step would not stay in cache (the fold's lookups jump in k).
      const double k1 = sigma > 0.0 ? std::min(12.0 / sigma, k_table) : 0.0;
      const auto f = [&](double k) {
        if (k == 0.0) return sigma == 0.0 ? rem(0.0) : 0.0;
        return rem.exact(k) * one_minus_window(k);
      };
      double f_max = 0.0;
      for (int i = 1; i <= 4096; ++i) f_max = std::max(f_max, std::abs(rem(k_s * i / 4096.0)));
      const double tol_r = options.tolerance * f_max;
      // R carries rounding noise ~ eps c_max / k (k H and Cinf cancel): the check allows it.
      const double noise = 64.0 * eps * c_max;
      const auto build = [&](double k_from, double k_to, double dk) {
        UniformTable t;
        for (int it = 0; it < 10; ++it) {
          t = UniformTable(f, k_from, dk, k_to);
          double err = 0.0;
          for (double k = k_from + 0.5 * dk; k < k_to; k += dk)
            if (k > 0.0) err = std::max(err, std::abs(t(k) - f(k)) - noise / k);
          if (err <= tol_r) break;
          dk *= 0.5;
        }
        return t;
      };
      const UniformTable table_lo = k1 > 0.0 ? build(0.0, k1, 0.02 / sigma) : UniformTable();
      const UniformTable table_hi =
          k_table > k1 ? build(k1, k_table, (k_table - k1) / 1024.0) : UniformTable();
      const auto short_table = [&](double k) { return k < k1 ? table_lo(k) : table_hi(k); };
      const std::ptrdiff_t sx = hx + 1;
      const std::ptrdiff_t sy = hy + 1;
      double* const fold = scratch(sx * sy);
      // Per-axis alias wavenumbers and sincs: k = 2 pi (xi + p)/d with xi = m/(2h) in [0, 1/2].
      const auto axis = [](std::ptrdiff_t h, int p_max, double d, std::vector<double>& kk,
                           std::vector<double>& ss) {
        const auto np = static_cast<std::size_t>(2 * p_max + 1);
        kk.assign(static_cast<std::size_t>(h + 1) * np, 0.0);
        ss.assign(kk.size(), 0.0);
        for (std::ptrdiff_t m = 0; m <= h; ++m)
          for (int p = -p_max; p <= p_max; ++p) {
            const double xi = static_cast<double>(m) / (2.0 * static_cast<double>(h)) + p;
            const auto idx = static_cast<std::size_t>(m) * np + static_cast<std::size_t>(p + p_max);
            kk[idx] = 2.0 * pi * xi / d;
            ss[idx] = sinc_pi(xi);
          }
      };
      std::vector<double> kxs;
      std::vector<double> sxs;
      std::vector<double> kys;
      std::vector<double> sys;
      axis(hx, px, dx, kxs, sxs);
      axis(hy, py, dy, kys, sys);
      const auto npx = static_cast<std::size_t>(2 * px + 1);
      const auto npy = static_cast<std::size_t>(2 * py + 1);
      const double k_s2 = k_s * k_s;
      // Square cells on a square lattice: F(m, n) = F(n, m) (R is radial), fold half of it.
      const bool symmetric = dx == dy && hx == hy && px == py;
      // Terms with |k| > k_s are zero, and the smallest |k| of (m, n) is that of p = q = 0
      // (|xi + p| >= xi for xi in [0, 1/2]), which grows with m: a row ends at the first m whose
      // p = q = 0 term is beyond k_s (at 1024^2 for TiN 50 um, k_s dx / 2 pi = 0.34: 63 % of the
      // lattice is zero).
      const auto k_min2 = [&](std::size_t ix, std::size_t iy) {
        return kxs[ix] * kxs[ix] + kys[iy] * kys[iy];
      };
      std::vector<std::ptrdiff_t> row_end(static_cast<std::size_t>(sy), 0);
      parallel_for(sy, threads, [&](std::ptrdiff_t n) {
        const std::size_t iy0 = static_cast<std::size_t>(n) * npy + static_cast<std::size_t>(py);
        std::ptrdiff_t m = symmetric ? n : 0;
        for (; m < sx; ++m) {
          if (k_min2(static_cast<std::size_t>(m) * npx + static_cast<std::size_t>(px), iy0) > k_s2)
            break;
          double sum = 0.0;
          for (std::size_t q = 0; q < npy; ++q) {
            const std::size_t iy = static_cast<std::size_t>(n) * npy + q;
            const double ky2 = kys[iy] * kys[iy];
            if (ky2 > k_s2) continue;
            double row = 0.0;
            for (std::size_t p = 0; p < npx; ++p) {
              const std::size_t ix = static_cast<std::size_t>(m) * npx + p;
              const double k2 = kxs[ix] * kxs[ix] + ky2;
              if (k2 > k_s2) continue;
              const double k = std::sqrt(k2);
              row += sxs[ix] * short_table(k);
            }
            sum += sys[iy] * row;
          }
          fold[n * sx + m] = sum;
        }
        row_end[static_cast<std::size_t>(n)] = m;
        std::fill(fold + n * sx + m, fold + (n + 1) * sx, 0.0);
      });
      if (symmetric) fill_lower_triangle(fold, sy, sx, threads);
      // Rows beyond the last one with a nonzero entry stay zero through the transform along x.
      std::ptrdiff_t rows = 0;
      for (std::ptrdiff_t n = 0; n < sy; ++n)
        if (row_end[static_cast<std::size_t>(n)] > (symmetric ? n : 0)) rows = n + 1;
      if (symmetric) rows = std::max(rows, row_end[0]);
      // The 2-D DCT-I (FFTW REDFT00) as two batches of 1-D transforms: along x over the nonzero
      // rows only, then along y over every column.
      const int nx_t = static_cast<int>(sx);
      const int ny_t = static_cast<int>(sy);
      FftwPlan along_x = FftwPlan::create(threads, [&] {
        const fftw_r2r_kind kind = FFTW_REDFT00;
        return fftw_plan_many_r2r(1, &nx_t, static_cast<int>(std::max<std::ptrdiff_t>(rows, 1)),
                                  fold, nullptr, 1, nx_t, fold, nullptr, 1, nx_t, &kind,
                                  FFTW_ESTIMATE);
      });
      FftwPlan along_y = FftwPlan::create(threads, [&] {
        const fftw_r2r_kind kind = FFTW_REDFT00;
        return fftw_plan_many_r2r(1, &ny_t, nx_t, fold, nullptr, nx_t, 1, fold, nullptr, nx_t, 1,
                                  &kind, FFTW_ESTIMATE);
      });
      along_x.execute();
      along_y.execute();
      // DCT-I of the even spectrum = the sum over the full period (1/(Mx My) = 1/(4 hx hy)).
      const double norm = 1.0 / (4.0 * static_cast<double>(hx) * static_cast<double>(hy));
      parallel_for(ny, threads, [&](std::ptrdiff_t j) {
        for (std::ptrdiff_t i = 0; i < nx; ++i) quarter(i, j) += norm * fold[j * sx + i];
      });
      rep.seconds_short = since(t_short);
    }
  }

  if (!ab_done) love_and_exponential(false);

  // The offsets nx and ny are never used by the convolution: 0 by convention.
  quarter_field.row(nx).setZero();
  quarter_field.col(ny).setZero();
  rep.seconds = since(t_start);
  if (report != nullptr) *report = rep;
  return {grid, std::move(quarter_field)};
}

InfluenceKernel split_frf_kernel(const Grid& grid, const Frf& frf,
                                 const SplitKernelOptions& options, SplitKernelReport* report) {
  return wrap_even_kernel(split_frf_kernel_quarter(grid, frf, options, report));
}

}  // namespace coatfft
