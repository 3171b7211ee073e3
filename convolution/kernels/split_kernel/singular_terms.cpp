#include <cmath>

#include "convolution/kernels/love_influence.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/kernels/split_kernel/detail/split_plan.hpp"
#include "core/detail/gauss_legendre.hpp"
#include "core/detail/parallel_for.hpp"

// (a) + (b) of the split kernel: Love's coefficients and the closed form of exp(-beta k)/k.
namespace coatfft::detail::split {
namespace {

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

}  // namespace

// quarter = (a) + (b) at every offset, or at the near cells only (r < 32 d) on the stencil
// route, whose pass over the point values assigns the far cells.
void assign_singular_terms(const SplitPlan& p, QuarterRows quarter) {
  const double near2 = p.near_r * p.near_r;
  detail::parallel_for(quarter.begin(p), quarter.end(p), p.threads, [&](std::ptrdiff_t j) {
    const double y = static_cast<double>(j) * p.dy;
    double* out = quarter.row(j);
    for (std::ptrdiff_t i = 0; i < p.nx; ++i) {
      const double x = static_cast<double>(i) * p.dx;
      // Squared distances decide the rules (hypot per cell was 6 % of the kernel's time).
      const double r2 = x * x + y * y;
      if (r2 < near2)
        out[i] = singular_terms_closed_form(p, x, y);
      else if (p.stencil)
        break;
      else
        out[i] = singular_terms_by_gauss(p, x, y, r2);
    }
  });
}

}  // namespace coatfft::detail::split
