#include "convolution/split_frf_kernel.hpp"

#include <fftw3.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "convolution/cell_average_stencil.hpp"
#include "convolution/fftw_plan.hpp"
#include "convolution/love_influence.hpp"
#include "core/detail/gauss_legendre.hpp"
#include "core/detail/lagrange.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

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

// ---- The remainder R(k) and the length scales of the FRF ------------------------------------

// The remainder R(k) = H(k) - Cinf/k - A exp(-beta k)/k of the split, A = C0 - Cinf: bounded at
// k = 0 (H = C0/k + O(1)) and decaying like max(exp(-beta k), |k H - Cinf|)/k.
class Remainder {
 public:
  Remainder() = default;
  Remainder(const Frf& frf, double c_inf, double A, double beta)
      : frf_(&frf), c_inf_(c_inf), A_(A), beta_(beta) {}

  // k H(k) - Cinf (dimension of C), checked.
  double q(double k) const {
    const double h = (*frf_)(k);
    COATFFT_REQUIRE(std::isfinite(h) && h > 0, "split_frf_kernel: the FRF '", frf_->name(),
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

// k H(k) - Cinf at log-spaced k (8 per decade), from where k H is C0 to where it is Cinf.
struct FrfSamples {
  std::vector<double> k;
  std::vector<double> q;
  double q_max = 0.0;
};

FrfSamples sample_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max) {
  const double tol_q = 64.0 * eps * c_max;
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
  for (std::size_t i = 0; i < s.k.size(); ++i) {
    s.k[i] = k_a * std::pow(10.0, static_cast<double>(i) / per_decade);
    s.q[i] = rem.q(s.k[i]);
    s.q_max = std::max(s.q_max, std::abs(s.q[i]));
  }
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

// What a log-spaced scan of k H(k) - Cinf tells about the FRF's length scales.
struct Scan {
  double k_lo = 0.0;  // below: R constant to ~1e-7 relative
  double k_hi = 0.0;  // above: |k H - Cinf| negligible
  double beta = 0.0;  // automatic beta
  bool remainder_zero = false;
};

Scan scan_frf(const Remainder& rem, double A, double c_max, double l_min, double l_max) {
  const FrfSamples s = sample_frf(rem, A, c_max, l_min, l_max);
  const std::size_t n = s.k.size();
  const double tol_q = 64.0 * eps * c_max;
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

// The window w = exp(-s) (1 + s + s^2/2), s = (sigma k)^2, of the Ewald-type split (Ewald 1921)
// R = R w + R (1 - w); sigma = 0 puts all of R in the short-range part, sigma = inf all of it in
// the long-range part. 1 - w = exp(-s) sum_{j>=3} s^j/j! = O(k^6): the short-range part then has
// the far field (sigma^6/6) (-lap)^3 of R's r^-3 tail, 1837 (sigma/r)^6 of it, so its periodic
// images (>= 32 sigma away) are negligible (a plain Gaussian, 1 - w = O(k^2), leaves
// 9 (sigma/r)^2: 1e-2 at 32 sigma).
double window(double sigma, double k) {
  if (sigma == 0.0) return 0.0;
  if (std::isinf(sigma)) return 1.0;
  const double s = (sigma * k) * (sigma * k);
  return std::exp(-s) * (1.0 + s * (1.0 + 0.5 * s));
}

// 1 - window(sigma, k), without the cancellation at small s.
double one_minus_window(double sigma, double k) {
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
}

// ---- Tables ------------------------------------------------------------------------------------

// a[j * stride + i] = a[i * stride + j] for 0 <= i < j < n: completes a symmetric n x n array of
// which the part i >= j was computed, in 64 x 64 tiles (a plain transposed copy is cache-bound).
void fill_lower_triangle(double* a, std::ptrdiff_t n, std::ptrdiff_t stride, int threads) {
  constexpr std::ptrdiff_t tile = 64;
  detail::parallel_for(0, (n + tile - 1) / tile, threads, [&](std::ptrdiff_t tj) {
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
                       double r_max, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(std::ceil(r_max / dr)) + 4;
  const double x_max = (kn.empty() ? 0.0 : kn.back()) * dr * static_cast<double>(n);
  constexpr double h = 1.0 / 64.0;
  const auto nj = static_cast<std::ptrdiff_t>(std::min(std::ceil(x_max / h), 65536.0)) + 4;
  std::vector<double> j0(static_cast<std::size_t>(nj));
  detail::parallel_for(0, nj, threads, [&](std::ptrdiff_t i) {
    j0[static_cast<std::size_t>(i)] = gsl_sf_bessel_J0(h * static_cast<double>(i));
  });
  const EvenTable bessel(j0, h);
  const double x_table = h * static_cast<double>(nj - 4);
  std::vector<double> g(static_cast<std::size_t>(n));
  detail::parallel_for(0, n, threads, [&](std::ptrdiff_t i) {
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
// centred 6-point stencil), quintic Lagrange interpolation (error ~ dk^6 f^(6) / 1000); 0 beyond
// k_max.
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
double sinc_pi(double x) {
  if (x == 0.0) return 1.0;
  return std::sin(pi * x) / (pi * x);
}

// Scratch memory shared by the long part's point values and the short part's fold (used one
// after the other): first touches of fresh memory cost ~0.6 ms per MiB on the development VM.
double* scratch(std::vector<double>& spare, std::ptrdiff_t n) {
  if (spare.size() < static_cast<std::size_t>(n)) spare.resize(static_cast<std::size_t>(n));
  return spare.data();
}

// ---- The plan: every parameter of the construction, chosen from the FRF and the options ------

struct SplitPlan {
  // The grid and the options.
  std::ptrdiff_t nx = 0;
  std::ptrdiff_t ny = 0;
  double dx = 0.0;
  double dy = 0.0;
  double lx = 0.0;
  double ly = 0.0;
  double d_max = 0.0;   // max(dx, dy)
  double near_r = 0.0;  // 32 d_max: closed forms inside, smooth over a cell outside
  double tolerance = 0.0;
  double log_tol = 0.0;  // ln(1 / tolerance)
  int max_alias_order = 0;
  int threads = 1;
  // The split H = Cinf/k + A exp(-beta k)/k + R(k), A = C0 - Cinf.
  double c0 = 0.0;
  double c_inf = 0.0;
  double A = 0.0;
  double c_max = 0.0;  // max(C0, Cinf): the scale of every tolerance
  double beta = 0.0;
  bool remainder_zero = false;
  Remainder remainder;  // R, tabulated in log k (unless remainder_zero)
  double k_lo = 0.0;    // below: R constant
  double k_r = 0.0;     // beyond: |R| k <= tolerance c_max
  // The window split R = R w + R (1 - w).
  double sigma = 0.0;  // 0: periodic route, inf: Hankel route
  double k_c = 0.0;    // beyond: R w negligible
  bool long_range = false;
  bool short_range = false;
  // The long-range part: Hankel panels in k, radial step, and the rule over each cell.
  std::vector<double> panel_edges;
  double r_max = 0.0;  // the domain's diagonal
  double dr = 0.0;
  double ell = 0.0;      // the long-range kernel is smooth on this length
  int cell_nodes = 0;    // Gauss-Legendre nodes per subcell side
  int subcells = 1;      // subdivisions of a cell side
  bool stencil = false;  // far cells by point values and the cell-average stencil
};

constexpr int hankel_panel_nodes = 16;

void check_options(const SplitKernelOptions& options) {
  COATFFT_REQUIRE(std::isfinite(options.beta) && options.beta >= 0,
                  "split_frf_kernel: beta = ", options.beta,
                  " m, but beta must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(std::isfinite(options.sigma) && options.sigma >= 0,
                  "split_frf_kernel: sigma = ", options.sigma,
                  " m, but sigma must be finite and >= 0 (0 = automatic)");
  COATFFT_REQUIRE(options.tolerance > 0 && options.tolerance <= 1e-3,
                  "split_frf_kernel: tolerance = ", options.tolerance,
                  ", but it must be in (0, 1e-3]");
  COATFFT_REQUIRE(options.threads >= 1 && options.threads <= max_threads,
                  "split_frf_kernel: threads = ", options.threads, ", but it must be in [1, ",
                  max_threads, "]");
  COATFFT_REQUIRE(options.max_alias_order >= 0 && options.max_alias_order <= 4096,
                  "split_frf_kernel: max_alias_order = ", options.max_alias_order,
                  ", but it must be in [0, 4096]");
}

// The window length sigma and the cut-offs of the two parts of R.
void choose_window(SplitPlan& p, const SplitKernelOptions& options) {
  p.sigma =
      options.sigma > 0 ? options.sigma : std::max(std::min(p.lx, p.ly) / 32.0, 1.5 * p.d_max);
  if (options.route == SplitRoute::periodic) p.sigma = 0.0;
  if (options.route == SplitRoute::hankel) p.sigma = std::numeric_limits<double>::infinity();
  // w < tol beyond k_c: exp(-s) s^2/2 < tol at s = log_tol + 2 log(log_tol) (two Newton-free
  // fixed-point steps suffice for the tolerances allowed).
  double s_c = p.log_tol;
  for (int it = 0; it < 4; ++it) s_c = p.log_tol + 2.0 * std::log(s_c) - std::log(2.0);
  p.k_c = std::isinf(p.sigma) ? p.k_r : std::min(p.k_r, std::sqrt(s_c) / p.sigma);
  p.long_range = p.sigma > 0.0 && p.k_c > 0.0;
  p.short_range = !std::isinf(p.sigma) && p.k_r > 0.0;
}

// Panels of the Hankel transform: geometric (halving) from the first uniform panel down to R's
// smallest scale, then uniform of width <= 2 pi / r_max (one J0 period at r_max) up to k_c.
std::vector<double> hankel_panel_edges(double k_c, double r_max, double k_lo) {
  const double dk_u = std::min(4.0 * pi / r_max, k_c);
  std::vector<double> edges = {0.0};
  std::vector<double> geo;
  for (double e = dk_u * 0.5; e > k_lo; e *= 0.5) geo.push_back(e);
  std::reverse(geo.begin(), geo.end());
  edges.insert(edges.end(), geo.begin(), geo.end());
  const auto nu = static_cast<std::ptrdiff_t>(std::ceil(k_c / dk_u));
  for (std::ptrdiff_t i = 1; i <= nu; ++i)
    edges.push_back(k_c * static_cast<double>(i) / static_cast<double>(nu));
  return edges;
}

// The Hankel table and the rule over each cell of the long-range part.
void choose_long_range_rules(SplitPlan& p) {
  p.r_max = std::hypot(p.lx, p.ly);
  p.panel_edges = hankel_panel_edges(p.k_c, p.r_max, p.k_lo);
  // g is band-limited to k_c: 6-point interpolation with k_c dr = 0.3 is accurate to ~1e-9 of
  // g's scale (checked against a table with half the step in the tests).
  p.dr = 0.5 / p.k_c;
  const double nodes = static_cast<double>(hankel_panel_nodes * (p.panel_edges.size() - 1));
  const double cost = nodes * (p.r_max / p.dr);
  COATFFT_REQUIRE(cost < 4e9, "split_frf_kernel: the Hankel table would need ", cost,
                  " Bessel evaluations (a layer much thinner than the domain with the hankel "
                  "route); use SplitRoute::automatic");
  // Gauss rule per cell: the kernel is smooth on the scale ell = sqrt(log_tol)/k_c (about sigma;
  // its spectrum is cut like a Gaussian of width sqrt(2) sigma). The n-point Gauss-Legendre
  // error on a cell of side d is about c_n (d/(sqrt(2) ell))^(2n) with c_2 = 2e-4, c_3 = 7e-7,
  // c_4 = 7e-9, c_5 = 3e-11, c_6 = 2e-12: n is picked for ~1e-13 relative, and cells larger than
  // 1.5 ell are subdivided.
  p.ell = std::sqrt(p.log_tol) / p.k_c;
  p.subcells = static_cast<int>(std::clamp(std::ceil(p.d_max / (p.ell / 1.5)), 1.0, 64.0));
  const double ratio = p.ell * p.subcells / p.d_max;
  p.cell_nodes = ratio >= 24.0 ? 2 : ratio >= 12.0 ? 3 : ratio >= 4.0 ? 4 : ratio >= 2.5 ? 5 : 6;
  // Where the long kernel is smooth on >= 8 cells, one point value per cell and the 9-point
  // cell-average stencil replace the rule (add_long_range_by_stencil).
  p.stencil = p.ell >= 8.0 * p.d_max;
}

SplitPlan make_split_plan(const Grid& grid, const Frf& frf, const SplitKernelOptions& options) {
  check_options(options);
  SplitPlan p;
  p.nx = grid.nx();
  p.ny = grid.ny();
  p.dx = grid.dx();
  p.dy = grid.dy();
  p.lx = grid.lx();
  p.ly = grid.ly();
  p.d_max = std::max(p.dx, p.dy);
  p.near_r = 32.0 * p.d_max;
  p.tolerance = options.tolerance;
  p.log_tol = std::log(1.0 / options.tolerance);
  p.max_alias_order = options.max_alias_order;
  p.threads = options.threads;
  p.c0 = frf.c0();
  p.c_inf = frf.c_inf();
  COATFFT_REQUIRE(std::isfinite(p.c0) && p.c0 > 0, "split_frf_kernel: c0 = ", p.c0,
                  " 1/Pa of FRF '", frf.name(), "', but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(p.c_inf) && p.c_inf > 0, "split_frf_kernel: c_inf = ", p.c_inf,
                  " 1/Pa of FRF '", frf.name(), "', but it must be finite and > 0");
  p.c_max = std::max(p.c0, p.c_inf);
  p.A = p.c0 - p.c_inf;
  const Remainder probe(frf, p.c_inf, p.A, 1.0);
  const Scan scan = scan_frf(probe, p.A, p.c_max, std::min(p.dx, p.dy), std::max(p.lx, p.ly));
  p.beta = p.A == 0.0 ? 0.0 : (options.beta > 0 ? options.beta : scan.beta);
  p.remainder_zero = scan.remainder_zero;
  p.k_lo = scan.k_lo;
  if (p.remainder_zero) return p;
  p.remainder = Remainder(frf, p.c_inf, p.A, p.beta);
  p.remainder.tabulate(scan.k_lo, std::max(scan.k_hi, p.A != 0.0 ? 50.0 / p.beta : 0.0), 400);
  p.k_r = remainder_cutoff(p.remainder, p.A, p.beta, p.tolerance * p.c_max);
  choose_window(p, options);
  if (p.long_range) choose_long_range_rules(p);
  return p;
}

// ---- (a) + (b): Love's coefficients and the closed form of exp(-beta k)/k --------------------

// (a) Cinf/k <-> Cinf/(2 pi r): Love's coefficients (Love 1929) for E* = 2/Cinf
// (docs/theory.md (1.5)), computed as love_kernel does (love_influence / E*);
// (b) A exp(-beta k)/k <-> A/(2 pi sqrt(r^2 + beta^2)): its cell integral
// split_rectangle_integral. Both in closed form, for the cells near the origin.
double singular_terms_closed_form(const SplitPlan& p, double x, double y) {
  const double love_E_star = 2.0 / p.c_inf;
  double v = love_influence(x, y, p.dx, p.dy) / love_E_star;
  if (p.A != 0.0)
    v += p.A / (2.0 * pi) * detail::split_rectangle_integral(x, y, p.dx, p.dy, p.beta);
  return v;
}

// The same beyond 32 d, squared distance r2: both kernels are analytic over the cell and the
// 4-corner sums cancel (log10((r/d)^2) digits lost), so both are integrated by one n x n
// Gauss-Legendre rule, which converges like rho^(-2n), rho ~ 4 r/d (Bernstein ellipse of the
// nearest singularity): n = 4 from 32 d, 3 from 64 d (rho^-6 < 4e-15), 2 from 512 d
// (rho^-4 < 6e-14 of a coefficient 512x smaller than K(0,0)); coarser than love_influence's
// rules (exact to rounding, docs in love_influence.cpp), by the tolerance of this kernel.
double singular_terms_by_gauss(const SplitPlan& p, double x, double y, double r2) {
  const double d = p.d_max;
  const int n = r2 >= (512.0 * d) * (512.0 * d) ? 2 : r2 >= (64.0 * d) * (64.0 * d) ? 3 : 4;
  const detail::GaussLegendreView rule = detail::gauss_legendre(n);
  const double ca = 0.25 * p.dx * p.dy * p.c_inf / (2.0 * pi);
  const double cb = 0.25 * p.dx * p.dy * p.A / (2.0 * pi);
  const double b2 = p.beta * p.beta;
  double sum = 0.0;
  for (std::size_t a = 0; a < rule.nodes.size(); ++a) {
    const double ex = x - 0.5 * p.dx * rule.nodes[a];
    double row = 0.0;
    for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
      const double ey = y - 0.5 * p.dy * rule.nodes[b];
      const double e2 = ex * ex + ey * ey;
      double f = ca / std::sqrt(e2);
      if (p.A != 0.0) f += cb / std::sqrt(e2 + b2);
      row += rule.weights[b] * f;
    }
    sum += rule.weights[a] * row;
  }
  return sum;
}

// quarter = (a) + (b) at every offset, or at the near cells only (r < 32 d) on the stencil
// route, whose pass over the point values assigns the far cells.
void assign_singular_terms(const SplitPlan& p, Field& quarter) {
  const double near2 = p.near_r * p.near_r;
  detail::parallel_for(0, p.ny, p.threads, [&](std::ptrdiff_t j) {
    const double y = static_cast<double>(j) * p.dy;
    for (std::ptrdiff_t i = 0; i < p.nx; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      // Squared distances decide the rules (hypot per cell was 6 % of the kernel's time).
      const double r2 = x * x + y * y;
      if (r2 < near2)
        quarter(i, j) = singular_terms_closed_form(p, x, y);
      else if (p.stencil)
        break;
      else
        quarter(i, j) = singular_terms_by_gauss(p, x, y, r2);
    }
  });
}

// ---- (c) long range, R w: Hankel table in r, quadrature over each cell ------------------------

// g(r) = (1/2 pi) int_0^kc R w J0(k r) k dk by 16-point Gauss-Legendre on each panel, tabulated
// in r up to the domain's diagonal (plus the stencil's reach).
EvenTable long_range_kernel(const SplitPlan& p) {
  const detail::GaussLegendreView g16 = detail::gauss_legendre(hankel_panel_nodes);
  std::vector<double> kn;
  std::vector<double> kw;
  for (std::size_t e = 0; e + 1 < p.panel_edges.size(); ++e) {
    const double mid = 0.5 * (p.panel_edges[e] + p.panel_edges[e + 1]);
    const double half = 0.5 * (p.panel_edges[e + 1] - p.panel_edges[e]);
    for (std::size_t q = 0; q < g16.nodes.size(); ++q) {
      const double k = mid + half * g16.nodes[q];
      kn.push_back(k);
      kw.push_back(half * g16.weights[q] * p.remainder.exact(k) * window(p.sigma, k) * k /
                   (2.0 * pi));
    }
  }
  return hankel_table(kw, kn, p.dr, p.r_max + 4.0 * p.d_max, p.threads);
}

// The product rule over a cell: offsets from the cell centre and weights (times the cell side),
// cell_nodes Gauss-Legendre nodes on each of `subcells` subintervals per side.
struct CellRule {
  std::vector<double> ox;
  std::vector<double> wx;
  std::vector<double> oy;
  std::vector<double> wy;
};

CellRule long_range_cell_rule(const SplitPlan& p) {
  const detail::GaussLegendreView g = detail::gauss_legendre(p.cell_nodes);
  const int sub = p.subcells;
  CellRule rule;
  for (int s = 0; s < sub; ++s)
    for (std::size_t q = 0; q < g.nodes.size(); ++q) {
      const double c = -0.5 + (s + 0.5) / sub;
      rule.ox.push_back((c + 0.5 * g.nodes[q] / sub) * p.dx);
      rule.wx.push_back(0.5 * g.weights[q] / sub * p.dx);
      rule.oy.push_back((c + 0.5 * g.nodes[q] / sub) * p.dy);
      rule.wy.push_back(0.5 * g.weights[q] / sub * p.dy);
    }
  return rule;
}

// The integral of g over cell (i, j).
double cell_integral(const SplitPlan& p, const EvenTable& g, const CellRule& rule, std::ptrdiff_t i,
                     std::ptrdiff_t j) {
  double sum = 0.0;
  for (std::size_t a = 0; a < rule.ox.size(); ++a) {
    const double x = static_cast<double>(i) * p.dx + rule.ox[a];
    double row = 0.0;
    for (std::size_t b = 0; b < rule.oy.size(); ++b) {
      const double y = static_cast<double>(j) * p.dy + rule.oy[b];
      row += rule.wy[b] * g(std::sqrt(x * x + y * y));
    }
    sum += rule.wx[a] * row;
  }
  return sum;
}

// Point values (times the cell area) of g + Cinf/(2 pi r) + A/(2 pi sqrt(r^2 + beta^2)) at
// i in [0, ex), j in [0, ey), into point[j * ex + i]; the kernel is even, so negative offsets
// read |i|, |j|. The origin's singular terms are left out: only near cells reach it. Square
// cells on a square grid: point(i, j) = point(j, i), only i >= j is evaluated.
void far_point_values(const SplitPlan& p, const EvenTable& g, double* point, std::ptrdiff_t ex,
                      std::ptrdiff_t ey) {
  const double fa = p.c_inf / (2.0 * pi) * p.dx * p.dy;
  const double fb = p.A / (2.0 * pi) * p.dx * p.dy;
  const double b2 = p.beta * p.beta;
  const bool symmetric = p.dx == p.dy && p.nx == p.ny;
  detail::parallel_for(0, ey, p.threads, [&](std::ptrdiff_t j) {
    const double y2 = (static_cast<double>(j) * p.dy) * (static_cast<double>(j) * p.dy);
    for (std::ptrdiff_t i = symmetric ? j : 0; i < ex; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      const double r2 = x * x + y2;
      const double r = std::sqrt(r2);
      double f = p.dx * p.dy * g(r);
      if (r2 > 0.0) {
        f += fa / r;
        if (p.A != 0.0) f += fb / std::sqrt(r2 + b2);
      }
      point[j * ex + i] = f;
    }
  });
  if (symmetric) fill_lower_triangle(point, ey, ex, p.threads);
}

// Stencil route (ell >= 8 d): the point values of far_point_values, averaged over each cell by
// the 9-point cell-average stencil along x and then along y (cell_average_stencil.hpp). Its error
// E (k d)^10 (E = 1.06e-5) is weighted by the spectrum R w (cut at k_c = 5.6/sigma, largest near
// 2/sigma); its error kernel is concentrated within ~sigma of the origin, where the near cells
// (r < 32 d) keep the Gauss rule: the coefficients change by < 1e-11 of K(0, 0)
// (docs/split_kernel.md, section 5). The far cells' (a) + (b) are smooth over a cell beyond 32 d
// and go through the same stencil (error ~E 10! (d/r)^10 of the coefficient there): one pass,
// one table lookup and one or two square roots per cell.
void add_long_range_by_stencil(const SplitPlan& p, const EvenTable& g, const CellRule& rule,
                               Field& quarter, std::vector<double>& spare) {
  constexpr std::ptrdiff_t m = detail::cell_average_half_width;
  const auto& c = detail::cell_average_weights;
  const std::ptrdiff_t ex = p.nx + m;
  const std::ptrdiff_t ey = p.ny + m;
  double* const point = scratch(spare, ex * ey);
  far_point_values(p, g, point, ex, ey);
  // Along x, in place: row j of `point` becomes its x average at i in [0, nx).
  detail::parallel_for(0, ey, p.threads, [&](std::ptrdiff_t j) {
    double* row = point + j * ex;
    const std::vector<double> in(row, row + ex);
    for (std::ptrdiff_t i = 0; i < p.nx; ++i) {
      double v = c[0] * in[static_cast<std::size_t>(i)];
      for (std::ptrdiff_t a = 1; a <= m; ++a)
        v += c[static_cast<std::size_t>(a)] *
             (in[static_cast<std::size_t>(std::abs(i - a))] + in[static_cast<std::size_t>(i + a)]);
      row[i] = v;
    }
  });
  // Along y into the far cells; the near cells add the Gauss rule to their closed forms.
  const double near2 = p.near_r * p.near_r;
  detail::parallel_for(0, p.ny, p.threads, [&](std::ptrdiff_t j) {
    std::array<const double*, 2 * m + 1> rows{};
    for (std::ptrdiff_t a = -m; a <= m; ++a)
      rows[static_cast<std::size_t>(a + m)] = point + std::abs(j + a) * ex;
    double* out = &quarter(0, j);
    const double y = static_cast<double>(j) * p.dy;
    std::ptrdiff_t i = 0;
    for (; i < p.nx; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      if (x * x + y * y >= near2) break;
      out[i] += cell_integral(p, g, rule, i, j);
    }
    for (; i < p.nx; ++i) {
      double v = c[0] * rows[m][i];
      for (std::ptrdiff_t a = 1; a <= m; ++a)
        v += c[static_cast<std::size_t>(a)] *
             (rows[static_cast<std::size_t>(m - a)][i] + rows[static_cast<std::size_t>(m + a)][i]);
      out[i] = v;
    }
  });
}

void add_long_range(const SplitPlan& p, Field& quarter, std::vector<double>& spare,
                    SplitKernelReport& rep) {
  const auto start = std::chrono::steady_clock::now();
  const EvenTable g = long_range_kernel(p);
  rep.hankel_r_points = g.size();
  rep.hankel_k_nodes = static_cast<std::ptrdiff_t>(hankel_panel_nodes * (p.panel_edges.size() - 1));
  const CellRule rule = long_range_cell_rule(p);
  if (p.stencil) {
    add_long_range_by_stencil(p, g, rule, quarter, spare);
  } else {
    detail::parallel_for(0, p.ny, p.threads, [&](std::ptrdiff_t j) {
      for (std::ptrdiff_t i = 0; i < p.nx; ++i) quarter(i, j) += cell_integral(p, g, rule, i, j);
    });
  }
  rep.seconds_long = detail::seconds_since(start);
}

// ---- (c) short range, R (1 - w): periodic lattice with the aliases folded --------------------

// The short-range spectrum S(k) = R (1 - w) on a uniform k grid up to the largest folded |k|
// (quintic interpolation, no logarithm per lookup: the fold makes ~N^2 pi P^2 lookups), refined
// until the midpoints match the exact R to tolerance x max|R|. Two segments: [0, k1] resolves the
// window (scale 1/sigma), [k1, k_table] R's own decay; one table at the finer step would not stay
// in cache (the fold's lookups jump in k).
class ShortRangeSpectrum {
 public:
  ShortRangeSpectrum(const SplitPlan& p, double k_table) : p_(p) {
    double f_max = 0.0;
    for (int i = 1; i <= 4096; ++i)
      f_max = std::max(f_max, std::abs(p.remainder(p.k_r * i / 4096.0)));
    tol_ = p.tolerance * f_max;
    // R carries rounding noise ~ eps c_max / k (k H and Cinf cancel): the check allows it.
    noise_ = 64.0 * eps * p.c_max;
    k1_ = p.sigma > 0.0 ? std::min(12.0 / p.sigma, k_table) : 0.0;
    if (k1_ > 0.0) lo_ = refined(0.0, k1_, 0.02 / p.sigma);
    if (k_table > k1_) hi_ = refined(k1_, k_table, (k_table - k1_) / 1024.0);
  }
  double operator()(double k) const { return k < k1_ ? lo_(k) : hi_(k); }

 private:
  double exact(double k) const {
    if (k == 0.0) return p_.sigma == 0.0 ? p_.remainder(0.0) : 0.0;
    return p_.remainder.exact(k) * one_minus_window(p_.sigma, k);
  }
  UniformTable refined(double k_from, double k_to, double dk) const {
    const auto f = [this](double k) { return exact(k); };
    UniformTable t;
    for (int it = 0; it < 10; ++it) {
      t = UniformTable(f, k_from, dk, k_to);
      double err = 0.0;
      for (double k = k_from + 0.5 * dk; k < k_to; k += dk)
        if (k > 0.0) err = std::max(err, std::abs(t(k) - f(k)) - noise_ / k);
      if (err <= tol_) break;
      dk *= 0.5;
    }
    return t;
  }

  const SplitPlan& p_;
  double tol_ = 0.0;
  double noise_ = 0.0;
  double k1_ = 0.0;
  UniformTable lo_;
  UniformTable hi_;
};

// One axis of the lattice: the alias wavenumbers k = 2 pi (xi + p)/d, xi = m/(2h) in [0, 1/2],
// and their sincs, at [m * count + (p + p_max)] for m in [0, h], |p| <= p_max.
struct AliasAxis {
  std::size_t count = 0;  // 2 p_max + 1
  std::vector<double> k;
  std::vector<double> sinc;
};

AliasAxis alias_axis(std::ptrdiff_t h, int p_max, double d) {
  AliasAxis axis;
  axis.count = static_cast<std::size_t>(2 * p_max + 1);
  axis.k.assign(static_cast<std::size_t>(h + 1) * axis.count, 0.0);
  axis.sinc.assign(axis.k.size(), 0.0);
  for (std::ptrdiff_t m = 0; m <= h; ++m)
    for (int p = -p_max; p <= p_max; ++p) {
      const double xi = static_cast<double>(m) / (2.0 * static_cast<double>(h)) + p;
      const auto idx =
          static_cast<std::size_t>(m) * axis.count + static_cast<std::size_t>(p + p_max);
      axis.k[idx] = 2.0 * pi * xi / d;
      axis.sinc[idx] = sinc_pi(xi);
    }
  return axis;
}

// The alias order |p| needed along a side d to fold every |k| < k_r, capped at max_alias_order.
int alias_order(const SplitPlan& p, double d, SplitKernelReport& rep) {
  const double need = std::ceil(p.k_r * d / (2.0 * pi) + 0.5);
  if (need > p.max_alias_order) rep.alias_capped = true;
  return static_cast<int>(std::min<double>(need, p.max_alias_order));
}

// fold[n * sx + m] = sum over the aliases (p, q) of sinc sinc S(|k|), m in [0, sx), n in [0, sy),
// the cell-averaged spectrum of the short-range part on the lattice; returns the number of
// leading rows n with a nonzero entry. Terms with |k| > k_r are zero, and the smallest |k| of
// (m, n) is that of p = q = 0 (|xi + p| >= xi for xi in [0, 1/2]), which grows with m: a row ends
// at the first m whose p = q = 0 term is beyond k_r (at 1024^2 for TiN 50 um, k_r dx / 2 pi =
// 0.34: 63 % of the lattice is zero).
std::ptrdiff_t fold_aliases(const SplitPlan& p, const ShortRangeSpectrum& spectrum,
                            const AliasAxis& ax, const AliasAxis& ay, bool symmetric, double* fold,
                            std::ptrdiff_t sx, std::ptrdiff_t sy) {
  const double k_s2 = p.k_r * p.k_r;
  const std::size_t npx = ax.count;
  const std::size_t npy = ay.count;
  std::vector<std::ptrdiff_t> row_end(static_cast<std::size_t>(sy), 0);
  detail::parallel_for(0, sy, p.threads, [&](std::ptrdiff_t n) {
    const auto iy0 = static_cast<std::size_t>(n) * npy;
    std::ptrdiff_t m = symmetric ? n : 0;
    for (; m < sx; ++m) {
      const auto ix0 = static_cast<std::size_t>(m) * npx;
      const double kx0 = ax.k[ix0 + npx / 2];
      const double ky0 = ay.k[iy0 + npy / 2];
      if (kx0 * kx0 + ky0 * ky0 > k_s2) break;
      double sum = 0.0;
      for (std::size_t q = 0; q < npy; ++q) {
        const double ky2 = ay.k[iy0 + q] * ay.k[iy0 + q];
        if (ky2 > k_s2) continue;
        double row = 0.0;
        for (std::size_t i = 0; i < npx; ++i) {
          const double k2 = ax.k[ix0 + i] * ax.k[ix0 + i] + ky2;
          if (k2 > k_s2) continue;
          row += ax.sinc[ix0 + i] * spectrum(std::sqrt(k2));
        }
        sum += ay.sinc[iy0 + q] * row;
      }
      fold[n * sx + m] = sum;
    }
    row_end[static_cast<std::size_t>(n)] = m;
    std::fill(fold + n * sx + m, fold + (n + 1) * sx, 0.0);
  });
  if (symmetric) fill_lower_triangle(fold, sy, sx, p.threads);
  std::ptrdiff_t rows = 0;
  for (std::ptrdiff_t n = 0; n < sy; ++n)
    if (row_end[static_cast<std::size_t>(n)] > (symmetric ? n : 0)) rows = n + 1;
  if (symmetric) rows = std::max(rows, row_end[0]);
  return rows;
}

// The 2-D DCT-I (FFTW REDFT00) of the sx x sy array `fold`, in place, as two batches of 1-D
// transforms: along x over the first `rows` rows only (the others are zero and stay so), then
// along y over every column.
void dct1_in_place(double* fold, std::ptrdiff_t sx, std::ptrdiff_t sy, std::ptrdiff_t rows,
                   int threads) {
  const int nx_t = static_cast<int>(sx);
  const int ny_t = static_cast<int>(sy);
  FftwPlan along_x = FftwPlan::create(threads, [&] {
    const fftw_r2r_kind kind = FFTW_REDFT00;
    return fftw_plan_many_r2r(1, &nx_t, static_cast<int>(std::max<std::ptrdiff_t>(rows, 1)), fold,
                              nullptr, 1, nx_t, fold, nullptr, 1, nx_t, &kind, FFTW_ESTIMATE);
  });
  FftwPlan along_y = FftwPlan::create(threads, [&] {
    const fftw_r2r_kind kind = FFTW_REDFT00;
    return fftw_plan_many_r2r(1, &ny_t, nx_t, fold, nullptr, nx_t, 1, fold, nullptr, nx_t, 1, &kind,
                              FFTW_ESTIMATE);
  });
  along_x.execute();
  along_y.execute();
}

void add_short_range(const SplitPlan& p, Field& quarter, std::vector<double>& spare,
                     SplitKernelReport& rep) {
  const auto start = std::chrono::steady_clock::now();
  // Half periods (in cells): the images of the short-range kernel stay >= 32 sigma away.
  const std::ptrdiff_t hx =
      std::max<std::ptrdiff_t>(p.nx, static_cast<std::ptrdiff_t>(std::ceil(32.0 * p.sigma / p.dx)));
  const std::ptrdiff_t hy =
      std::max<std::ptrdiff_t>(p.ny, static_cast<std::ptrdiff_t>(std::ceil(32.0 * p.sigma / p.dy)));
  const int px = alias_order(p, p.dx, rep);
  const int py = alias_order(p, p.dy, rep);
  rep.alias_order = std::max(px, py);
  const double k_table =
      std::min(p.k_r, std::hypot(2.0 * pi * (px + 0.5) / p.dx, 2.0 * pi * (py + 0.5) / p.dy));
  const ShortRangeSpectrum spectrum(p, k_table);
  const std::ptrdiff_t sx = hx + 1;
  const std::ptrdiff_t sy = hy + 1;
  double* const fold = scratch(spare, sx * sy);
  // Square cells on a square lattice: F(m, n) = F(n, m) (R is radial), fold half of it.
  const bool symmetric = p.dx == p.dy && hx == hy && px == py;
  const std::ptrdiff_t rows = fold_aliases(p, spectrum, alias_axis(hx, px, p.dx),
                                           alias_axis(hy, py, p.dy), symmetric, fold, sx, sy);
  dct1_in_place(fold, sx, sy, rows, p.threads);
  // DCT-I of the even spectrum = the sum over the full period (1/(Mx My) = 1/(4 hx hy)).
  const double norm = 1.0 / (4.0 * static_cast<double>(hx) * static_cast<double>(hy));
  detail::parallel_for(0, p.ny, p.threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = 0; i < p.nx; ++i) quarter(i, j) += norm * fold[j * sx + i];
  });
  rep.seconds_short = detail::seconds_since(start);
}

// What the plan chose, for the report.
void report_plan(const SplitPlan& p, SplitKernelReport& rep) {
  rep.c0 = p.c0;
  rep.c_inf = p.c_inf;
  rep.beta = p.beta;
  rep.remainder_zero = p.remainder_zero;
  if (p.remainder_zero) return;
  rep.sigma = p.sigma;
  if (p.long_range) rep.cell_rule = p.stencil ? 1 : p.cell_nodes * p.subcells;
}

}  // namespace

// The method of split_frf_kernel.hpp, part by part. The kernel is even in x and y: only its
// quarter di, dj >= 0 is computed (DcfftOperator transforms it directly, and the (2nx, 2ny)
// wrap-around array, 32 MiB at 1024^2, is never formed).
InfluenceKernel split_frf_kernel(const Grid& grid, const Frf& frf,
                                 const SplitKernelOptions& options, SplitKernelReport* report) {
  const auto start = std::chrono::steady_clock::now();
  const SplitPlan plan = make_split_plan(grid, frf, options);
  SplitKernelReport rep;
  report_plan(plan, rep);
  Field quarter(plan.nx + 1, plan.ny + 1);
  std::vector<double> spare;             // scratch shared by the two parts of R
  assign_singular_terms(plan, quarter);  // (a) + (b)
  if (plan.long_range) add_long_range(plan, quarter, spare, rep);    // (c) R w
  if (plan.short_range) add_short_range(plan, quarter, spare, rep);  // (c) R (1 - w)
  // The offsets nx and ny are never used by the convolution: 0 by convention.
  quarter.row(plan.nx).setZero();
  quarter.col(plan.ny).setZero();
  rep.seconds = detail::seconds_since(start);
  if (report != nullptr) *report = rep;
  return InfluenceKernel(grid, InfluenceKernel::Form::coefficients, std::move(quarter),
                         Method::frf_split);
}

}  // namespace coatfft
