#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "convolution/kernels/detail/cell_average_stencil.hpp"
#include "convolution/kernels/split_kernel/detail/split_plan.hpp"
#include "convolution/kernels/split_kernel/detail/tables.hpp"
#include "core/detail/gauss_legendre.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"

// (c) long range of the split kernel, R w: Hankel table in r, quadrature over each cell.
namespace coatfft::detail::split {
namespace {

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
// i in [0, ex), j in [j0, j1), into point[(j - j0) * ex + i]; the kernel is even, so negative
// offsets read |i|, |j|. The origin's singular terms are left out: only near cells reach it.
// Square cells on a square grid, all rows: point(i, j) = point(j, i), only i >= j is evaluated.
void far_point_values(const SplitPlan& p, const RadialTable& g, double* point, std::ptrdiff_t ex,
                      std::ptrdiff_t j0, std::ptrdiff_t j1) {
  const double fa = p.c_inf / (2.0 * pi) * p.dx * p.dy;
  const double fb = p.A / (2.0 * pi) * p.dx * p.dy;
  const double b2 = p.beta * p.beta;
  const bool symmetric = p.dx == p.dy && p.nx == p.ny && j0 == 0 && j1 == ex;
  detail::parallel_for(j0, j1, p.threads, [&](std::ptrdiff_t j) {
    const double y2 = (static_cast<double>(j) * p.dy) * (static_cast<double>(j) * p.dy);
    double* row = point + (j - j0) * ex;
    for (std::ptrdiff_t i = symmetric ? j : 0; i < ex; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      const double r2 = x * x + y2;
      const double r = std::sqrt(r2);
      double f = p.dx * p.dy * g(r);
      if (r2 > 0.0) {
        f += fa / r;
        if (p.A != 0.0) f += fb / std::sqrt(r2 + b2);
      }
      row[i] = f;
    }
  });
  if (symmetric) fill_lower_triangle(point, j1, ex, p.threads);
}

// Stencil route (ell >= 8 d): the point values of far_point_values, averaged over each cell by
// the 9-point cell-average stencil along x and then along y (cell_average_stencil.hpp). Its error
// E (k d)^10 (E = 1.06e-5) is weighted by the spectrum R w (cut at k_c = 5.6/sigma, largest near
// 2/sigma); its error kernel is concentrated within ~sigma of the origin, where the near cells
// (r < 32 d) keep the Gauss rule: the coefficients change by < 1e-11 of K(0, 0)
// (docs/split_kernel.md, section 5). The far cells' (a) + (b) are smooth over a cell beyond 32 d
// and go through the same stencil (error ~E 10! (d/r)^10 of the coefficient there): one pass,
// one table lookup and one or two square roots per cell.
// The rows j of `quarter` read the point rows |j + a|, |a| <= m: [max(0, begin - m), end + m).
void add_long_range_by_stencil(const SplitPlan& p, const RadialTable& g, const AxisCells& cx,
                               const AxisCells& cy, QuarterRows quarter,
                               std::vector<double>& spare) {
  constexpr std::ptrdiff_t m = detail::cell_average_half_width;
  const auto& c = detail::cell_average_weights;
  const std::ptrdiff_t ex = p.nx + m;
  const std::ptrdiff_t j0 = std::max<std::ptrdiff_t>(quarter.begin(p) - m, 0);
  const std::ptrdiff_t j1 = quarter.end(p) + m;
  if (quarter.begin(p) == quarter.end(p)) return;
  double* const point = scratch(spare, ex * (j1 - j0));
  far_point_values(p, g, point, ex, j0, j1);
  // Along x, in place: row j of `point` becomes its x average at i in [0, nx).
  detail::parallel_for(0, j1 - j0, p.threads, [&](std::ptrdiff_t j) {
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
  detail::parallel_for(quarter.begin(p), quarter.end(p), p.threads, [&](std::ptrdiff_t j) {
    std::array<const double*, 2 * m + 1> rows{};
    for (std::ptrdiff_t a = -m; a <= m; ++a)
      rows[static_cast<std::size_t>(a + m)] = point + (std::abs(j + a) - j0) * ex;
    double* out = quarter.row(j);
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

}  // namespace

void add_long_range(const SplitPlan& p, QuarterRows quarter, std::vector<double>& spare,
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
    detail::parallel_for(quarter.begin(p), quarter.end(p), p.threads, [&](std::ptrdiff_t j) {
      CellQuadrature q{cx, cy, {}, {}};
      double* out = quarter.row(j);
      for (std::ptrdiff_t i = 0; i < p.nx; ++i) out[i] += cell_integral(g, q, i, j);
    });
  }
  rep.seconds_long = detail::seconds_since(start);
}

}  // namespace coatfft::detail::split
