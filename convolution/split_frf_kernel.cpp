#include "convolution/split_frf_kernel.hpp"

#include <fftw3.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "convolution/cell_average_stencil.hpp"
#include "convolution/ewald_window.hpp"
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

using std::numbers::pi;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// ---- The remainder R(k) and the length scales of the FRF ------------------------------------

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

// The window of the split R = R w + R (1 - w), convolution/ewald_window.hpp.
double window(double sigma, double k) {
  return detail::ewald_window(sigma, k);
}
double one_minus_window(double sigma, double k) {
  return detail::ewald_window_complement(sigma, k);
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

// The long part's rule along one axis of the cells: `sub` panels of `nodes` Gauss-Legendre points
// per cell, or panels graded away from the origin (graded_rule) where more than
// max_uniform_panels would be needed.
struct AxisQuadrature {
  int sub = 1;
  int nodes = 2;
  bool graded = false;
};

// One axis of the short-range lattice: half period h cells (0: a wide axis, add_short_range) and
// the alias order folded.
struct LatticeAxis {
  std::ptrdiff_t h = 0;
  int p_max = 0;
  bool capped = false;  // the fold needed more than max_alias_order
};

struct SplitPlan {
  // The grid and the options.
  std::ptrdiff_t nx = 0;
  std::ptrdiff_t ny = 0;
  double dx = 0.0;
  double dy = 0.0;
  double lx = 0.0;
  double ly = 0.0;
  double d_min = 0.0;   // min(dx, dy)
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
  double s_c = 0.0;    // (sigma k)^2 beyond which w < tolerance
  double k_c = 0.0;    // beyond: R w negligible
  bool long_range = false;
  bool short_range = false;
  // Axes along which a cell is >= 128 sigma long (wide_cells): the short-range kernel lies
  // within the cell's own row, so the lattice along that axis collapses to its k = 0 term
  // (add_short_range).
  bool wide_x = false;
  bool wide_y = false;
  LatticeAxis lattice_x;
  LatticeAxis lattice_y;
  double lattice_entries = 0.0;  // of the short-range fold (require_lattice)
  // The long-range part: Hankel panels in k, radial steps, and the rule over each cell.
  std::vector<double> panel_edges;  // of the uniform table
  double r_max = 0.0;               // the domain's diagonal plus the stencil's reach
  double r_uniform = 0.0;           // the uniform table's end; beyond, the logarithmic tail
  double dr = 0.0;
  double ell = 0.0;  // the long-range kernel is smooth on this length
  AxisQuadrature quad_x;
  AxisQuadrature quad_y;
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

// The alias order |p| that folds every |k| < k_r along a cell side d.
double alias_need(const SplitPlan& p, double d) {
  return std::ceil(p.k_r * d / (2.0 * pi) + 0.5);
}

// A cell side >= wide_cells sigma is a wide axis (add_short_range): the short-range kernel is
// left out beyond half of it, 64 sigma. It decays like r^-9 in R's far field, but where R has a
// length scale b above sigma it is (sigma^6/6) (-lap)^3 of R's kernel and reaches a few b, and a
// wide cell collects it over its whole length: cut at 32 sigma (cells of 0.5 um x 2 mm,
// b = 6 sigma) it cost 7e-10 of K(0, 0), at 64 sigma 1e-11.
constexpr double wide_cells = 128.0;

// The default window length: min(lx, ly)/32, so that the Hankel table costs the same for every
// N, but at least 1.5 times the shorter cell side, so that the long part needs no subdivision of
// the cells across. Not the longer side: the lattice half-size 32 sigma/d along the short side
// would grow with the cell aspect ratio (48 dy/dx with 1.5 max(dx, dy)); the long side is
// subdivided instead (axis_quadrature, graded_rule). A side >= 8 times the other that needs more
// than 4 aliases (a layer thinner than ~1/4 of that side) gets sigma = side/128, which makes the
// axis wide: it then needs no alias at all, where the fold would cost (2P + 1) terms per lattice
// entry or be truncated at max_alias_order (1 x 4096 cells of 2 mm x 0.5 um, TiN 20 um:
// P = 469), and the long part's rules, graded in r, cost a few points per far cell. The short
// side stays within 16 sigma.
double automatic_sigma(const SplitPlan& p) {
  double sigma = std::max(std::min(p.lx, p.ly) / 32.0, 1.5 * p.d_min);
  const double many_aliases = std::min(4, p.max_alias_order);
  for (const double d : {p.dx, p.dy})
    if (alias_need(p, d) > many_aliases && d / wide_cells >= p.d_min / 16.0)
      sigma = std::min(sigma, d / wide_cells);
  return sigma;
}

// The window length sigma and the cut-offs of the two parts of R.
void choose_window(SplitPlan& p, const SplitKernelOptions& options) {
  p.sigma = options.sigma > 0 ? options.sigma : automatic_sigma(p);
  if (options.route == SplitRoute::periodic) p.sigma = 0.0;
  if (options.route == SplitRoute::hankel) p.sigma = std::numeric_limits<double>::infinity();
  // w < tol beyond k_c: exp(-s) s^2/2 < tol at s = log_tol + 2 log(log_tol) (two Newton-free
  // fixed-point steps suffice for the tolerances allowed).
  p.s_c = p.log_tol;
  for (int it = 0; it < 4; ++it) p.s_c = p.log_tol + 2.0 * std::log(p.s_c) - std::log(2.0);
  p.k_c = std::isinf(p.sigma) ? p.k_r : std::min(p.k_r, std::sqrt(p.s_c) / p.sigma);
  p.long_range = p.sigma > 0.0 && p.k_c > 0.0;
  p.short_range = !std::isinf(p.sigma) && p.k_r > 0.0;
  p.wide_x = p.short_range && p.sigma > 0.0 && p.dx >= wide_cells * p.sigma;
  p.wide_y = p.short_range && p.sigma > 0.0 && p.dy >= wide_cells * p.sigma;
}

// Largest number of lattice entries (doubles) of the short-range fold: 2^27, 1 GiB.
constexpr double max_lattice_entries = 134217728.0;

// The reach of the short-range kernel that the lattice keeps free of images along one axis:
// 32 sigma, or 64 sigma when the other axis is wide, for the reasons of wide_cells (a wide cell
// weighs the images by its length; cells of 83 um x 8.3 mm, b = 8 sigma: 1.3e-9 of K(0, 0) at
// 32 sigma, 1e-11 at 64 sigma; the 1-D lattice of a wide cell costs little either way).
double lattice_reach(const SplitPlan& p, bool other_wide) {
  return (other_wide ? 64.0 : 32.0) * p.sigma;
}

// One axis of the lattice: the half period keeps the images of the short-range kernel beyond
// lattice_reach (and >= the domain, so that every offset is an entry); the alias order folds
// every |k| < k_r, capped at max_alias_order.
LatticeAxis lattice_axis(const SplitPlan& p, std::ptrdiff_t n, double d, bool wide,
                         bool other_wide) {
  if (wide) return {};
  LatticeAxis a;
  a.h = static_cast<std::ptrdiff_t>(
      std::max(static_cast<double>(n), std::ceil(lattice_reach(p, other_wide) / d)));
  const double need = alias_need(p, d);
  a.capped = need > p.max_alias_order;
  a.p_max = static_cast<int>(std::min<double>(need, p.max_alias_order));
  return a;
}

// The lattice of the short-range part. Its size is checked by require_lattice before any
// allocation; a plan whose lattice would not fit gets no axes, so that the work estimate of a grid
// the split kernel cannot take stays cheap.
void choose_lattice(SplitPlan& p) {
  const double hx =
      std::max(static_cast<double>(p.nx), std::ceil(lattice_reach(p, p.wide_y) / p.dx));
  const double hy =
      std::max(static_cast<double>(p.ny), std::ceil(lattice_reach(p, p.wide_x) / p.dy));
  p.lattice_entries = (p.wide_x ? 1.0 : hx + 1.0) * (p.wide_y ? 1.0 : hy + 1.0);
  if (p.lattice_entries > max_lattice_entries) return;
  p.lattice_x = lattice_axis(p, p.nx, p.dx, p.wide_x, p.wide_y);
  p.lattice_y = lattice_axis(p, p.ny, p.dy, p.wide_y, p.wide_x);
}

// A lattice that would not fit is refused before it is allocated: a sigma given by the caller
// that is huge against a cell, or a grid of more than ~11585^2 cells (the lattice covers every
// offset of the domain); the automatic sigma keeps the half sizes <= max(2n, 96).
void require_lattice(const SplitPlan& p) {
  COATFFT_REQUIRE(p.lattice_entries <= max_lattice_entries, "split_frf_kernel: sigma = ", p.sigma,
                  " m against cells of ", p.dx, " x ", p.dy, " m on ", p.nx, " x ", p.ny,
                  " cells needs a short-range lattice of ", p.lattice_entries,
                  " entries (more than ", max_lattice_entries,
                  "); use fewer cells, leave sigma automatic (0), or use frf-spectral");
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

// Gauss-Legendre points per panel for a panel `ratio` times shorter than the length on which the
// kernel is smooth. The n-point error on a panel of width w is about c_n (w/(sqrt(2) ell))^(2n)
// with c_2 = 2e-4, c_3 = 7e-7, c_4 = 7e-9, c_5 = 3e-11, c_6 = 2e-12: ~1e-13 relative.
int nodes_for_ratio(double ratio) {
  return ratio >= 24.0 ? 2 : ratio >= 12.0 ? 3 : ratio >= 4.0 ? 4 : ratio >= 2.5 ? 5 : 6;
}

// Beyond this many uniform panels per cell side the panels are graded (graded_rule).
constexpr double max_uniform_panels = 8.0;

// Panels of <= ell/1.5 per cell side d.
AxisQuadrature axis_quadrature(double ell, double d) {
  AxisQuadrature q;
  const double sub = std::ceil(d / (ell / 1.5));
  q.graded = sub > max_uniform_panels;
  q.sub = static_cast<int>(std::clamp(sub, 1.0, max_uniform_panels));
  q.nodes = nodes_for_ratio(ell * q.sub / d);
  return q;
}

// The Hankel table and the rule over each cell of the long-range part.
void choose_long_range_rules(SplitPlan& p) {
  p.r_max = std::hypot(p.lx, p.ly) + 4.0 * p.d_max;  // the stencil reads 4 cells beyond
  // The uniform table (step 0.5/k_c) stops at 128 sigma_e, sigma_e = sqrt(s_c)/k_c the window
  // length of the band limit; the tail beyond is tabulated in log r (tail_table). Domains up
  // to an aspect ratio of ~4 (r_max ~ 45 sigma when square) never reach it.
  const double sigma_e = std::sqrt(p.s_c) / p.k_c;
  p.r_uniform =
      p.r_max <= 128.0 * sigma_e ? std::numeric_limits<double>::infinity() : 128.0 * sigma_e;
  const double r_table = std::min(p.r_max, p.r_uniform);
  p.panel_edges = hankel_panel_edges(p.k_c, std::min(std::hypot(p.lx, p.ly), r_table), p.k_lo);
  // g is band-limited to k_c: 6-point interpolation with k_c dr = 0.3 is accurate to ~1e-9 of
  // g's scale (checked against a table with half the step in the tests).
  p.dr = 0.5 / p.k_c;
  const double nodes = static_cast<double>(hankel_panel_nodes * (p.panel_edges.size() - 1));
  const double cost = nodes * (r_table / p.dr);
  // Bounded through r_uniform (a few million at most); kept as a guard before the allocation.
  COATFFT_REQUIRE(cost < 4e9, "split_frf_kernel: the Hankel table would need ", cost,
                  " Bessel evaluations; use SplitRoute::automatic");
  // Rule per cell and axis: the kernel is smooth on the scale ell = sqrt(log_tol)/k_c (about
  // sigma; its spectrum is cut like a Gaussian of width sqrt(2) sigma); panels <= ell/1.5.
  p.ell = std::sqrt(p.log_tol) / p.k_c;
  p.quad_x = axis_quadrature(p.ell, p.dx);
  p.quad_y = axis_quadrature(p.ell, p.dy);
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
  p.d_min = std::min(p.dx, p.dy);
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
  if (p.short_range) choose_lattice(p);
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

// Gauss-Legendre nodes and weights on the panels `edges`; the caller multiplies the weights by
// the integrand's factors, all nodes at once (an FRF is sampled in one batch, Frf::evaluate).
void panel_rule(const std::vector<double>& edges, std::vector<double>& kn,
                std::vector<double>& kw) {
  const detail::GaussLegendreView g16 = detail::gauss_legendre(hankel_panel_nodes);
  for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
    const double mid = 0.5 * (edges[e] + edges[e + 1]);
    const double half = 0.5 * (edges[e + 1] - edges[e]);
    for (std::size_t q = 0; q < g16.nodes.size(); ++q) {
      kn.push_back(mid + half * g16.nodes[q]);
      kw.push_back(half * g16.weights[q]);
    }
  }
}

// g(r) = (1/2 pi) int_0^kc R w J0(k r) k dk by 16-point Gauss-Legendre on each panel, tabulated
// in r up to the domain's diagonal (plus the stencil's reach) or up to r_uniform.
EvenTable long_range_kernel(const SplitPlan& p) {
  std::vector<double> kn;
  std::vector<double> kw;
  panel_rule(p.panel_edges, kn, kw);
  std::vector<double> r(kn.size());
  p.remainder.exact(kn, r);
  for (std::size_t j = 0; j < kn.size(); ++j)
    kw[j] *= r[j] * window(p.sigma, kn[j]) * kn[j] / (2.0 * pi);
  return hankel_table(kw, kn, p.dr, std::min(p.r_max, p.r_uniform), p.threads);
}

// The long-range kernel g(r): the uniform table below r_uniform, r^3 g(r) on a logarithmic table
// beyond (tail_table), and 0 past the tail's end.
class RadialTable {
 public:
  RadialTable(EvenTable uniform, double r_uniform, std::vector<double> tail, double u0, double du)
      : uniform_(std::move(uniform)),
        r_uniform_(r_uniform),
        tail_(std::move(tail)),
        u0_(u0),
        inv_du_(1.0 / du) {}
  std::ptrdiff_t size() const {
    return uniform_.size() + static_cast<std::ptrdiff_t>(tail_.size());
  }
  double operator()(double r) const {
    if (r < r_uniform_) return uniform_(r);
    const double s = (std::log(r) - u0_) * inv_du_;  // >= 3 for r >= r_uniform
    const auto i0 = static_cast<std::ptrdiff_t>(s);
    if (i0 + 3 >= static_cast<std::ptrdiff_t>(tail_.size())) return 0.0;
    return detail::lagrange6(tail_.data() + i0 - 2, s - static_cast<double>(i0)) / (r * r * r);
  }

 private:
  EvenTable uniform_;
  double r_uniform_;
  std::vector<double> tail_;
  double u0_;
  double inv_du_;
};

// Steps of the tail table per decade of r.
constexpr int tail_per_decade = 200;

// The tail r >= r_uniform of the long-range kernel. On the uniform step the table would need
// (k_c r_max)^2 Bessel terms, the square of the domain's aspect ratio (2e8 for 24 x 24 cells on
// 2 mm x 200 mm). Beyond 32 sigma the long kernel is R's own kernel up to the short part's far
// field, 1837 (sigma/r)^6 of R's r^-3 tail (the window's section of split_frf_kernel.hpp), and so
// is the kernel of R w(sigma_r) for sigma_r = r/32: at radius r the window may be widened to r/32,
// g(r) = (1/2 pi) int R(k) w(k r/32) J0(k r) k dk = (1/(2 pi r^2)) int R(t/r) w(t/32) J0(t) t dt,
// whose nodes t_j and weights (all but R) are the same for every r: ~600 table lookups of R per
// radius. Tabulated as r^3 g (constant for an r^-3 tail), 200 per decade, up to r_max or to the
// first decade over which |g| stays below 1e-2 tolerance of the (a) kernel c_inf/(2 pi r).
std::vector<double> tail_table(const SplitPlan& p, double u0, double du) {
  std::vector<double> tn;
  std::vector<double> tw;
  const double t_c = 32.0 * std::sqrt(p.s_c);
  panel_rule(hankel_panel_edges(t_c, 1.0, std::exp(u0) * p.k_lo), tn, tw);
  for (std::size_t j = 0; j < tn.size(); ++j)
    tw[j] *= window(1.0 / 32.0, tn[j]) * gsl_sf_bessel_J0(tn[j]) * tn[j] / (2.0 * pi);
  const auto n_end = static_cast<std::ptrdiff_t>(std::ceil((std::log(p.r_max) - u0) / du)) + 4;
  const double negligible = 1e-2 * p.tolerance * p.c_inf / (2.0 * pi);
  std::vector<double> tail;
  for (std::ptrdiff_t i0 = 0; i0 < n_end; i0 += tail_per_decade) {
    const std::ptrdiff_t i1 = std::min(n_end, i0 + tail_per_decade);
    tail.resize(static_cast<std::size_t>(i1));
    detail::parallel_for(i0, i1, p.threads, [&](std::ptrdiff_t i) {
      const double r = std::exp(u0 + du * static_cast<double>(i));
      double sum = 0.0;
      for (std::size_t j = 0; j < tn.size(); ++j) sum += tw[j] * p.remainder(tn[j] / r);
      tail[static_cast<std::size_t>(i)] = r * sum;  // r^3 g(r)
    });
    bool small = i1 - i0 == tail_per_decade && i0 > 0;
    for (std::ptrdiff_t i = i0; i < i1 && small; ++i) {
      const double r = std::exp(u0 + du * static_cast<double>(i));
      small = std::abs(tail[static_cast<std::size_t>(i)]) <= negligible * r * r;
    }
    if (small) break;  // the lookups beyond return 0
  }
  return tail;
}

// The whole long-range kernel: the uniform table and, where the domain reaches past r_uniform,
// the tail.
RadialTable long_range_table(const SplitPlan& p) {
  EvenTable uniform = long_range_kernel(p);
  if (std::isinf(p.r_uniform)) return RadialTable(std::move(uniform), p.r_uniform, {}, 0.0, 1.0);
  const double du = std::log(10.0) / tail_per_decade;
  const double u0 = std::log(p.r_uniform) - 3.0 * du;
  return RadialTable(std::move(uniform), p.r_uniform, tail_table(p, u0, du), u0, du);
}

// A rule along one axis: positions (relative to a shift) and weights.
struct AxisRule {
  std::vector<double> t;
  std::vector<double> w;
};

void append_panel(double a, double b, int n, AxisRule& rule) {
  const detail::GaussLegendreView g = detail::gauss_legendre(n);
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  for (std::size_t q = 0; q < g.nodes.size(); ++q) {
    rule.t.push_back(mid + half * g.nodes[q]);
    rule.w.push_back(half * g.weights[q]);
  }
}

// Panels of [a, b], 0 <= a < b (mirrored to [-b, -a] when sign < 0), graded away from the origin
// (r >= hypot(t, rho), rho the distance of the cell across). Near the origin the long kernel is
// smooth on ell: panels of lambda/1.5, lambda = max(ell, r/8), nodes_for_ratio. From r = 16 ell
// on it is R's kernel up to the short part's far field (tail_table), analytic off r = 0 (its
// complex singularities, such as r = +-i beta of the (b) kernel, are no nearer): a panel of width
// r/4 centred >= r from the nearest singularity has a Bernstein ellipse of parameter >= 16, and
// 5 points converge like 16^-10 = 1e-12 (4 panels and 20 points per factor e in r).
void graded_rule(double a, double b, double rho, double ell, double sign, AxisRule& rule) {
  for (double u = a; u < b;) {
    const double r = std::hypot(u, rho);
    const bool far = r >= 16.0 * ell;
    const double lambda = std::max(ell, r / 8.0);
    const double v = std::min(b, u + (far ? r / 4.0 : lambda / 1.5));
    const int n = far ? 5 : nodes_for_ratio(lambda / (v - u));
    if (sign > 0)
      append_panel(u, v, n, rule);
    else
      append_panel(-v, -u, n, rule);
    u = v;
  }
}

// The long part's rule along one axis of the cells: uniform offsets from the cell centre, shared
// by every cell (as x = i dx + offset), or graded positions built per cell.
class AxisCells {
 public:
  AxisCells(const AxisQuadrature& q, double ell, double d) : q_(q), ell_(ell), d_(d) {
    if (q.graded) return;
    const detail::GaussLegendreView g = detail::gauss_legendre(q.nodes);
    for (int s = 0; s < q.sub; ++s)
      for (std::size_t k = 0; k < g.nodes.size(); ++k) {
        const double c = -0.5 + (s + 0.5) / q.sub;
        uniform_.t.push_back((c + 0.5 * g.nodes[k] / q.sub) * d);
        uniform_.w.push_back(0.5 * g.weights[k] / q.sub * d);
      }
  }
  // The rule of the cell at offset i >= 0, rho its distance across: positions shift + t.
  const AxisRule& rule(std::ptrdiff_t i, double rho, AxisRule& scratch, double& shift) const {
    const double c = static_cast<double>(i) * d_;
    if (!q_.graded) {
      shift = c;
      return uniform_;
    }
    shift = 0.0;
    scratch.t.clear();
    scratch.w.clear();
    const double a = c - 0.5 * d_;
    if (a < 0.0) graded_rule(0.0, -a, rho, ell_, -1.0, scratch);
    graded_rule(std::max(a, 0.0), c + 0.5 * d_, rho, ell_, 1.0, scratch);
    return scratch;
  }
  // The distance from the origin to the cell at offset i >= 0 along this axis.
  double distance(std::ptrdiff_t i) const {
    return i == 0 ? 0.0 : (static_cast<double>(i) - 0.5) * d_;
  }

 private:
  AxisQuadrature q_;
  double ell_;
  double d_;
  AxisRule uniform_;
};

// The long part's cell quadrature: the rules of both axes and scratch for graded ones (one per
// thread).
struct CellQuadrature {
  const AxisCells& x;
  const AxisCells& y;
  AxisRule scratch_x;
  AxisRule scratch_y;
};

// The integral of g over cell (i, j).
double cell_integral(const RadialTable& g, CellQuadrature& q, std::ptrdiff_t i, std::ptrdiff_t j) {
  double sx = 0.0;
  double sy = 0.0;
  const AxisRule& rx = q.x.rule(i, q.y.distance(j), q.scratch_x, sx);
  const AxisRule& ry = q.y.rule(j, q.x.distance(i), q.scratch_y, sy);
  double sum = 0.0;
  for (std::size_t a = 0; a < rx.t.size(); ++a) {
    const double x = sx + rx.t[a];
    double row = 0.0;
    for (std::size_t b = 0; b < ry.t.size(); ++b) {
      const double y = sy + ry.t[b];
      row += ry.w[b] * g(std::sqrt(x * x + y * y));
    }
    sum += rx.w[a] * row;
  }
  return sum;
}

// Point values (times the cell area) of g + Cinf/(2 pi r) + A/(2 pi sqrt(r^2 + beta^2)) at
// i in [0, ex), j in [0, ey), into point[j * ex + i]; the kernel is even, so negative offsets
// read |i|, |j|. The origin's singular terms are left out: only near cells reach it. Square
// cells on a square grid: point(i, j) = point(j, i), only i >= j is evaluated.
void far_point_values(const SplitPlan& p, const RadialTable& g, double* point, std::ptrdiff_t ex,
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
void add_long_range_by_stencil(const SplitPlan& p, const RadialTable& g, const AxisCells& cx,
                               const AxisCells& cy, Field& quarter, std::vector<double>& spare) {
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
    CellQuadrature q{cx, cy, {}, {}};
    for (; i < p.nx; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      if (x * x + y * y >= near2) break;
      out[i] += cell_integral(g, q, i, j);
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
  const RadialTable g = long_range_table(p);
  rep.hankel_r_points = g.size();
  rep.hankel_k_nodes = static_cast<std::ptrdiff_t>(hankel_panel_nodes * (p.panel_edges.size() - 1));
  const AxisCells cx(p.quad_x, p.ell, p.dx);
  const AxisCells cy(p.quad_y, p.ell, p.dy);
  if (p.stencil) {
    add_long_range_by_stencil(p, g, cx, cy, quarter, spare);
  } else {
    detail::parallel_for(0, p.ny, p.threads, [&](std::ptrdiff_t j) {
      CellQuadrature q{cx, cy, {}, {}};
      for (std::ptrdiff_t i = 0; i < p.nx; ++i) quarter(i, j) += cell_integral(g, q, i, j);
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
    // R carries rounding noise ~ kEpsilon c_max / k (k H and Cinf cancel): the check allows it.
    noise_ = 64.0 * kEpsilon * p.c_max;
    k1_ = p.sigma > 0.0 ? std::min(12.0 / p.sigma, k_table) : 0.0;
    if (k1_ > 0.0) lo_ = refined(0.0, k1_, 0.02 / p.sigma);
    if (k_table > k1_) hi_ = refined(k1_, k_table, (k_table - k1_) / 1024.0);
  }
  double operator()(double k) const { return k < k1_ ? lo_(k) : hi_(k); }

 private:
  // S at every k >= 0 of `k`; those > 0 in one batch (Frf::evaluate). At k = 0, where H is
  // infinite, the limit: R(0) from the table times 1 - w(0) (1 for sigma = 0, else 0).
  std::vector<double> exact(const std::vector<double>& k) const {
    std::vector<double> positive;
    positive.reserve(k.size());
    for (const double ki : k)
      if (ki != 0.0) positive.push_back(ki);
    std::vector<double> r(positive.size());
    p_.remainder.exact(positive, r);
    std::vector<double> v(k.size());
    for (std::size_t i = 0, j = 0; i < k.size(); ++i) {
      if (k[i] != 0.0)
        v[i] = r[j++] * one_minus_window(p_.sigma, k[i]);
      else
        v[i] = p_.sigma == 0.0 ? p_.remainder(0.0) : 0.0;
    }
    return v;
  }
  // The largest error of `t` at the midpoints of its nodes, less R's rounding noise there.
  double midpoint_error(const UniformTable& t, double k_from, double k_to, double dk) const {
    std::vector<double> mid;
    for (double k = k_from + 0.5 * dk; k < k_to; k += dk)
      if (k > 0.0) mid.push_back(k);
    const std::vector<double> f = exact(mid);
    double err = 0.0;
    for (std::size_t i = 0; i < mid.size(); ++i)
      err = std::max(err, std::abs(t(mid[i]) - f[i]) - noise_ / mid[i]);
    return err;
  }
  UniformTable refined(double k_from, double k_to, double dk) const {
    const auto f = [this](const std::vector<double>& k) { return exact(k); };
    UniformTable t;
    for (int it = 0; it < 10; ++it) {
      t = UniformTable(f, k_from, dk, k_to);
      if (midpoint_error(t, k_from, k_to, dk) <= tol_) break;
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
// and their sincs, at [m * count + (p + p_max)] for m in [0, h], |p| <= p_max. A wide axis
// (h = 0) has the single term k = 0 of weight 1: its sum over k of d sinc(k d/2) S(k) e^(i k y)
// / (period), a box average, becomes (1/2 pi) int d sinc(k d/2) S(k) dk -> S(0) at y = 0 when
// the kernel of S is much shorter than the cell d (and 0 at the other cells).
struct AliasAxis {
  std::size_t count = 0;  // 2 p_max + 1
  std::vector<double> k;
  std::vector<double> sinc;
};

AliasAxis alias_axis(std::ptrdiff_t h, int p_max, double d) {
  AliasAxis axis;
  if (h == 0) {
    axis.count = 1;
    axis.k = {0.0};
    axis.sinc = {1.0};
    return axis;
  }
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

// sum_p sinc_p S(sqrt(k_p^2 + ky2)) over the aliases of lattice index m (entries ix0 + i of
// `ax`) with k_p^2 + ky2 <= k_s2. Along p, |k_p| grows on either side of p = 0 (xi in [0, 1/2]),
// so these terms are one run around p = 0 and both loops stop at its ends: the cost is the
// number of terms kept, not (2 p_max + 1).
double alias_row(const AliasAxis& ax, std::size_t ix0, double ky2, double k_s2,
                 const ShortRangeSpectrum& spectrum) {
  const std::size_t c = ax.count / 2;
  double row = 0.0;
  for (std::size_t i = c; i < ax.count; ++i) {
    const double k2 = ax.k[ix0 + i] * ax.k[ix0 + i] + ky2;
    if (k2 > k_s2) break;
    row += ax.sinc[ix0 + i] * spectrum(std::sqrt(k2));
  }
  for (std::size_t i = c; i-- > 0;) {
    const double k2 = ax.k[ix0 + i] * ax.k[ix0 + i] + ky2;
    if (k2 > k_s2) break;
    row += ax.sinc[ix0 + i] * spectrum(std::sqrt(k2));
  }
  return row;
}

// The alias sum of lattice entry (m, n): the same run structure along q.
double alias_sum(const AliasAxis& ax, const AliasAxis& ay, std::size_t ix0, std::size_t iy0,
                 double k_s2, const ShortRangeSpectrum& spectrum) {
  const std::size_t c = ay.count / 2;
  double sum = 0.0;
  for (std::size_t q = c; q < ay.count; ++q) {
    const double ky2 = ay.k[iy0 + q] * ay.k[iy0 + q];
    if (ky2 > k_s2) break;
    sum += ay.sinc[iy0 + q] * alias_row(ax, ix0, ky2, k_s2, spectrum);
  }
  for (std::size_t q = c; q-- > 0;) {
    const double ky2 = ay.k[iy0 + q] * ay.k[iy0 + q];
    if (ky2 > k_s2) break;
    sum += ay.sinc[iy0 + q] * alias_row(ax, ix0, ky2, k_s2, spectrum);
  }
  return sum;
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
      fold[n * sx + m] = alias_sum(ax, ay, ix0, iy0, k_s2, spectrum);
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
// along y over every column. An axis of length 1 (a wide axis) is left as it is.
void dct1_in_place(double* fold, std::ptrdiff_t sx, std::ptrdiff_t sy, std::ptrdiff_t rows,
                   int threads) {
  const int nx_t = static_cast<int>(sx);
  const int ny_t = static_cast<int>(sy);
  const fftw_r2r_kind kind = FFTW_REDFT00;
  if (sx > 1) {
    FftwPlan along_x = FftwPlan::create(threads, [&] {
      return fftw_plan_many_r2r(1, &nx_t, static_cast<int>(std::max<std::ptrdiff_t>(rows, 1)), fold,
                                nullptr, 1, nx_t, fold, nullptr, 1, nx_t, &kind, FFTW_ESTIMATE);
    });
    along_x.execute();
  }
  if (sy > 1) {
    FftwPlan along_y = FftwPlan::create(threads, [&] {
      return fftw_plan_many_r2r(1, &ny_t, nx_t, fold, nullptr, nx_t, 1, fold, nullptr, nx_t, 1,
                                &kind, FFTW_ESTIMATE);
    });
    along_y.execute();
  }
}

// The largest |k| that the fold reaches along a lattice axis (0 on a wide axis).
double lattice_k_max(const LatticeAxis& a, double d) {
  return a.h == 0 ? 0.0 : 2.0 * pi * (a.p_max + 0.5) / d;
}

void add_short_range(const SplitPlan& p, Field& quarter, std::vector<double>& spare,
                     SplitKernelReport& rep) {
  const auto start = std::chrono::steady_clock::now();
  // Both axes wide: only S(0) = R(0) (1 - w(0)) = 0 is left.
  if (p.lattice_x.h == 0 && p.lattice_y.h == 0) return;
  const LatticeAxis& lx = p.lattice_x;
  const LatticeAxis& ly = p.lattice_y;
  const double k_table =
      std::min(p.k_r, std::hypot(lattice_k_max(lx, p.dx), lattice_k_max(ly, p.dy)));
  const ShortRangeSpectrum spectrum(p, k_table);
  const std::ptrdiff_t sx = lx.h + 1;
  const std::ptrdiff_t sy = ly.h + 1;
  double* const fold = scratch(spare, sx * sy);
  // Square cells on a square lattice: F(m, n) = F(n, m) (R is radial), fold half of it.
  const bool symmetric = p.dx == p.dy && lx.h == ly.h && lx.p_max == ly.p_max;
  const std::ptrdiff_t rows =
      fold_aliases(p, spectrum, alias_axis(lx.h, lx.p_max, p.dx), alias_axis(ly.h, ly.p_max, p.dy),
                   symmetric, fold, sx, sy);
  dct1_in_place(fold, sx, sy, rows, p.threads);
  // DCT-I of the even spectrum = the sum over the full period (1/(Mx My) = 1/(4 hx hy)); a wide
  // axis contributes its cell's row only, with weight 1.
  const double norm = (lx.h > 0 ? 0.5 / static_cast<double>(lx.h) : 1.0) *
                      (ly.h > 0 ? 0.5 / static_cast<double>(ly.h) : 1.0);
  const std::ptrdiff_t mx = lx.h > 0 ? p.nx : 1;
  const std::ptrdiff_t my = ly.h > 0 ? p.ny : 1;
  detail::parallel_for(0, my, p.threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = 0; i < mx; ++i) quarter(i, j) += norm * fold[j * sx + i];
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
  rep.alias_order = std::max(p.lattice_x.p_max, p.lattice_y.p_max);
  rep.alias_capped = p.lattice_x.capped || p.lattice_y.capped;
  rep.wide_x = p.wide_x;
  rep.wide_y = p.wide_y;
  if (!p.long_range) return;
  const bool graded = p.quad_x.graded || p.quad_y.graded;
  rep.cell_rule = p.stencil ? 1
                  : graded  ? 0
                           : std::max(p.quad_x.nodes * p.quad_x.sub, p.quad_y.nodes * p.quad_y.sub);
}

// Work counts of the plan (split_frf_kernel_work): the fold visits the lattice entries inside
// |k| < k_r (spacing pi/(h d) along an axis), each summing its (2 p_max + 1) aliases per axis
// (half of them on a symmetric lattice); the long part evaluates its Hankel table and a rule of
// nodes^2 points per cell (9 with the stencil, ~8 panels per side when graded).
double fold_terms(const SplitPlan& p) {
  if (!p.short_range || (p.lattice_x.h == 0 && p.lattice_y.h == 0)) return 0.0;
  const auto axis_entries = [&](const LatticeAxis& a, double d) {
    if (a.h == 0) return 1.0;
    return std::min(static_cast<double>(a.h + 1), p.k_r * static_cast<double>(a.h) * d / pi + 1);
  };
  const auto aliases = [](const LatticeAxis& a) { return a.h == 0 ? 1.0 : 2.0 * a.p_max + 1.0; };
  const double entries = axis_entries(p.lattice_x, p.dx) * axis_entries(p.lattice_y, p.dy);
  const bool symmetric = p.dx == p.dy && p.lattice_x.h == p.lattice_y.h;
  return (symmetric ? 0.5 : 1.0) * (pi / 4.0) * entries * aliases(p.lattice_x) *
         aliases(p.lattice_y);
}

double cell_nodes(const SplitPlan& p) {
  const double cells = static_cast<double>(p.nx) * static_cast<double>(p.ny);
  if (p.stencil) return 9.0 * cells;
  const auto per_axis = [](const AxisQuadrature& q) { return q.graded ? 16.0 : q.nodes * q.sub; };
  return cells * per_axis(p.quad_x) * per_axis(p.quad_y);
}

}  // namespace

SplitKernelWork split_frf_kernel_work(const Grid& grid, const Frf& frf,
                                      const SplitKernelOptions& options) {
  const SplitPlan p = make_split_plan(grid, frf, options);
  SplitKernelWork work;
  work.lattice_entries = p.lattice_entries;
  work.lattice_fits = p.lattice_entries <= max_lattice_entries;
  work.remainder_zero = p.remainder_zero;
  if (p.remainder_zero) return work;
  work.fold_terms = fold_terms(p);
  if (p.long_range) {
    const double r_table = std::min(p.r_max, p.r_uniform);
    const double nodes = static_cast<double>(hankel_panel_nodes * (p.panel_edges.size() - 1));
    work.hankel_evaluations = nodes * r_table / p.dr;
    work.cell_nodes = cell_nodes(p);
  }
  return work;
}

// The method of split_frf_kernel.hpp, part by part. The kernel is even in x and y: only its
// quarter di, dj >= 0 is computed (DcfftOperator transforms it directly, and the (2nx, 2ny)
// wrap-around array, 32 MiB at 1024^2, is never formed).
InfluenceKernel split_frf_kernel(const Grid& grid, const Frf& frf,
                                 const SplitKernelOptions& options, SplitKernelReport* report) {
  const auto start = std::chrono::steady_clock::now();
  const SplitPlan plan = make_split_plan(grid, frf, options);
  require_lattice(plan);
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
