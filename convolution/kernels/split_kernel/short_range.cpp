#include <fftw3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/split_kernel/detail/split_plan.hpp"
#include "convolution/kernels/split_kernel/detail/tables.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

// (c) short range of the split kernel, R (1 - w): periodic lattice with the aliases folded.
namespace coatfft::detail::split {
namespace {

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

// fold[(n - n0) * sx + m] = sum over the aliases (p, q) of sinc sinc S(|k|), m in [0, sx), n in
// [n0, n0 + count), the cell-averaged spectrum of the short-range part on the lattice; returns
// the number of leading rows with a nonzero entry. Terms with |k| > k_r are zero, and the smallest
// |k| of (m, n) is that of p = q = 0 (|xi + p| >= xi for xi in [0, 1/2]), which grows with m: a
// row ends at the first m whose p = q = 0 term is beyond k_r (at 1024^2 for TiN 50 um,
// k_r dx / 2 pi = 0.34: 63 % of the lattice is zero). `symmetric` (every row): only m >= n.
std::ptrdiff_t fold_aliases(const SplitPlan& p, const ShortRangeSpectrum& spectrum,
                            const AliasAxis& ax, const AliasAxis& ay, bool symmetric, double* fold,
                            std::ptrdiff_t sx, std::ptrdiff_t n0, std::ptrdiff_t count) {
  const double k_s2 = p.k_r * p.k_r;
  const std::size_t npx = ax.count;
  const std::size_t npy = ay.count;
  std::vector<std::ptrdiff_t> row_end(static_cast<std::size_t>(count), 0);
  detail::parallel_for(0, count, p.threads, [&](std::ptrdiff_t r) {
    const std::ptrdiff_t n = n0 + r;
    const auto iy0 = static_cast<std::size_t>(n) * npy;
    double* row = fold + r * sx;
    std::ptrdiff_t m = symmetric ? n : 0;
    for (; m < sx; ++m) {
      const auto ix0 = static_cast<std::size_t>(m) * npx;
      const double kx0 = ax.k[ix0 + npx / 2];
      const double ky0 = ay.k[iy0 + npy / 2];
      if (kx0 * kx0 + ky0 * ky0 > k_s2) break;
      row[m] = alias_sum(ax, ay, ix0, iy0, k_s2, spectrum);
    }
    row_end[static_cast<std::size_t>(r)] = m;
    std::fill(row + m, row + sx, 0.0);
  });
  if (symmetric) fill_lower_triangle(fold, count, sx, p.threads);
  std::ptrdiff_t rows = 0;
  for (std::ptrdiff_t n = 0; n < count; ++n)
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

// The fold's spectrum table and alias axes: built once per fold, from the plan alone.
struct FoldInputs {
  explicit FoldInputs(const SplitPlan& p)
      : spectrum(p, std::min(p.k_r, std::hypot(lattice_k_max(p.lattice_x, p.dx),
                                               lattice_k_max(p.lattice_y, p.dy)))),
        ax(alias_axis(p.lattice_x.h, p.lattice_x.p_max, p.dx)),
        ay(alias_axis(p.lattice_y.h, p.lattice_y.p_max, p.dy)) {}
  ShortRangeSpectrum spectrum;
  AliasAxis ax;
  AliasAxis ay;
};

}  // namespace

ShortRangeLattice short_range_lattice(const SplitPlan& p) {
  const LatticeAxis& lx = p.lattice_x;
  const LatticeAxis& ly = p.lattice_y;
  ShortRangeLattice l;
  // Both axes wide: only S(0) = R(0) (1 - w(0)) = 0 is left.
  l.empty = !p.short_range || (lx.h == 0 && ly.h == 0);
  l.sx = lx.h + 1;
  l.sy = ly.h + 1;
  // DCT-I of the even spectrum = the sum over the full period (1/(Mx My) = 1/(4 hx hy)); a wide
  // axis contributes its cell's row only, with weight 1.
  l.norm = (lx.h > 0 ? 0.5 / static_cast<double>(lx.h) : 1.0) *
           (ly.h > 0 ? 0.5 / static_cast<double>(ly.h) : 1.0);
  l.mx = lx.h > 0 ? p.nx : 1;
  l.my = ly.h > 0 ? p.ny : 1;
  return l;
}

void fold_lattice_rows(const SplitPlan& p, std::ptrdiff_t n0, std::ptrdiff_t count, double* fold) {
  const FoldInputs in(p);
  fold_aliases(p, in.spectrum, in.ax, in.ay, false, fold, p.lattice_x.h + 1, n0, count);
}

void add_short_range(const SplitPlan& p, QuarterRows quarter, std::vector<double>& spare,
                     SplitKernelReport& rep) {
  const auto start = std::chrono::steady_clock::now();
  const ShortRangeLattice l = short_range_lattice(p);
  if (l.empty) return;
  const FoldInputs in(p);
  double* const fold = scratch(spare, l.sx * l.sy);
  // Square cells on a square lattice: F(m, n) = F(n, m) (R is radial), fold half of it.
  const bool symmetric =
      p.dx == p.dy && p.lattice_x.h == p.lattice_y.h && p.lattice_x.p_max == p.lattice_y.p_max;
  const std::ptrdiff_t rows =
      fold_aliases(p, in.spectrum, in.ax, in.ay, symmetric, fold, l.sx, 0, l.sy);
  dct1_in_place(fold, l.sx, l.sy, rows, p.threads);
  detail::parallel_for(quarter.begin(p), std::min(quarter.end(p), l.my), p.threads,
                       [&](std::ptrdiff_t j) {
                         double* out = quarter.row(j);
                         for (std::ptrdiff_t i = 0; i < l.mx; ++i)
                           out[i] += l.norm * fold[j * l.sx + i];
                       });
  rep.seconds_short = detail::seconds_since(start);
}

}  // namespace coatfft::detail::split
