#include "convolution/g0.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <chrono>
#include <cmath>
#include <numbers>
#include <queue>
#include <vector>

#include "core/error.hpp"

namespace coatfft {
namespace {

using std::numbers::pi;

struct Estimate {
  double value = 0.0;
  double error = 0.0;
};

// Globally adaptive quadrature (QUADPACK QAG strategy): keep a heap of panels, bisect the one
// with the largest error estimate until the summed estimate is below max(abs_tol, rel_tol |Q|)
// or `max_panels` is reached. The panel rule is Boost's Gauss-Kronrod (error |K - G|). Boost's own
// adaptive driver splits its tolerance in half per level, so with the absolute tolerance needed
// here (see compute_g0) it could not stop early on a remainder that is pure rounding noise.
template <unsigned Points, typename F>
Estimate adaptive_gauss_kronrod(const F& f, double a, double b, double abs_tol, double rel_tol,
                                int max_panels) {
  using Rule = boost::math::quadrature::gauss_kronrod<double, Points>;
  struct Panel {
    double a, b, value, error;
    bool operator<(const Panel& o) const { return error < o.error; }
  };
  auto make = [&](double lo, double hi) {
    double err = 0.0;
    const double v = Rule::integrate(f, lo, hi, 0, 0.0, &err);
    return Panel{lo, hi, v, err};
  };
  std::priority_queue<Panel> heap;
  const double min_width = 1e-15 * (b - a);
  Estimate total;
  const Panel first = make(a, b);
  heap.push(first);
  total.value = first.value;
  total.error = first.error;
  int panels = 1;
  while (panels < max_panels && total.error > std::max(abs_tol, rel_tol * std::abs(total.value))) {
    const Panel worst = heap.top();
    // Panels narrower than 1e-15 of the interval are not split: below that the nodes of a panel
    // touching a singular end point round onto it (H(0) = inf), and no tolerance a caller can
    // meet in double precision needs them.
    if (worst.b - worst.a < min_width) break;
    heap.pop();
    const double mid = 0.5 * (worst.a + worst.b);
    const Panel left = make(worst.a, mid), right = make(mid, worst.b);
    total.value += left.value + right.value - worst.value;
    total.error += left.error + right.error - worst.error;
    heap.push(left);
    heap.push(right);
    ++panels;
  }
  // Re-sum to shed the rounding of the running updates.
  total.value = 0.0;
  total.error = 0.0;
  while (!heap.empty()) {
    total.value += heap.top().value;
    total.error += heap.top().error;
    heap.pop();
  }
  return total;
}

// \iint_cell (H(|k|) - C0/|k|) dk for the cell [-X, X] x [-Y, Y]. For a radial integrand,
// \iint_rect f(|k|) dk = \int_0^D f(rho) rho w(rho) d rho, with w(rho) the angle of the circle of
// radius rho inside the rectangle: 2 pi for rho <= m = min(X, Y), 2 pi - 4 acos(m/rho) up to
// M = max(X, Y), then 2 pi - 4 acos(X/rho) - 4 acos(Y/rho) up to the corner D. Here
// f rho = rho H - C0 =: s(rho), bounded and smooth (theory.md 3.2). The square-root kinks of w at
// m and M are removed by rho = m / cos(phi) resp. M / cos(phi), for which acos(m/rho) = phi: this
// is the polar-sector integral of theory.md 3.2 with the angular integration done exactly.
Estimate remainder_integral(const Frf& frf, double X, double Y, double abs_tol) {
  const double c0 = frf.c0();
  const double m = std::min(X, Y), M = std::max(X, Y), D = std::hypot(X, Y);
  auto s = [&](double rho) { return rho * frf(rho) - c0; };
  constexpr int max_panels = 200;
  // Piece A: rho in [0, m], full circle.
  Estimate a = adaptive_gauss_kronrod<31>([&](double rho) { return 2.0 * pi * s(rho); }, 0.0, m,
                                          abs_tol / 3.0, 0.0, max_panels);
  // Piece B: rho in [m, M], circle cut by the near sides only.
  Estimate b;
  if (M > m) {
    b = adaptive_gauss_kronrod<31>(
        [&](double phi) {
          const double c = std::cos(phi);
          const double rho = m / c;
          return s(rho) * (2.0 * pi - 4.0 * phi) * m * std::sin(phi) / (c * c);
        },
        0.0, std::acos(m / M), abs_tol / 3.0, 0.0, max_panels);
  }
  // Piece C: rho in [M, D], cut by all four sides.
  Estimate c = adaptive_gauss_kronrod<31>(
      [&](double phi) {
        const double cs = std::cos(phi);
        const double rho = M / cs;
        const double other = (M > m) ? std::acos(std::min(m / rho, 1.0)) : phi;
        const double w = std::max(2.0 * pi - 4.0 * phi - 4.0 * other, 0.0);
        return s(rho) * w * M * std::sin(phi) / (cs * cs);
      },
      0.0, std::acos(M / D), abs_tol / 3.0, 0.0, max_panels);
  return {a.value + b.value + c.value, a.error + b.error + c.error};
}

// A 15 x 15 tensor Gauss-Kronrod rule with its embedded 7 x 7 Gauss rule, nodes and weights from
// Boost.Math on [-1, 1]: the panel rule of the 2-D adaptive quadrature below.
struct TensorGaussKronrod {
  std::vector<double> x, wk, wg;  // 15 nodes, Kronrod weights, Gauss weights (0 off the Gauss set)
  TensorGaussKronrod() {
    using K = boost::math::quadrature::gauss_kronrod<double, 15>;
    using G = boost::math::quadrature::gauss<double, 7>;
    const auto& ka = K::abscissa();
    const auto& kw = K::weights();
    const auto& ga = G::abscissa();
    const auto& gw = G::weights();
    for (std::size_t i = 0; i < ka.size(); ++i)
      for (const double sign : {-1.0, 1.0}) {
        if (i == 0 && sign > 0) continue;  // the centre node appears once
        double g = 0.0;
        for (std::size_t j = 0; j < ga.size(); ++j)
          if (std::abs(ga[j] - ka[i]) < 1e-15) g = gw[j];
        x.push_back(sign * ka[i]);
        wk.push_back(kw[i]);
        wg.push_back(g);
      }
  }
};

// Plain adaptive 2-D quadrature of H over the quadrant [0, X] x [0, Y] (the cell is 4 such
// quadrants), globally adaptive over rectangles like Matlab's quad2d used by the seed: a heap of
// rectangles, each integrated by the 15 x 15 Gauss-Kronrod tensor rule with error |K - G|; the
// worst one is split in four until the summed error is below tol |Q|. The 1/k singularity sits at
// the corner (0, 0), so refinement piles up there: about log2(1/tol) levels of ever smaller
// rectangles, and the error estimate is only as good as the rule's on a singular integrand.
Estimate quadrature_integral(const Frf& frf, double X, double Y, double tol) {
  static const TensorGaussKronrod rule;
  constexpr int max_rectangles = 20000;
  struct Rect {
    double x0, x1, y0, y1, value, error;
    bool operator<(const Rect& o) const { return error < o.error; }
  };
  auto make = [&](double x0, double x1, double y0, double y1) {
    const double cx = 0.5 * (x0 + x1), hx = 0.5 * (x1 - x0);
    const double cy = 0.5 * (y0 + y1), hy = 0.5 * (y1 - y0);
    double k = 0.0, g = 0.0;
    for (std::size_t i = 0; i < rule.x.size(); ++i)
      for (std::size_t j = 0; j < rule.x.size(); ++j) {
        const double f = frf(std::hypot(cx + hx * rule.x[i], cy + hy * rule.x[j]));
        k += rule.wk[i] * rule.wk[j] * f;
        g += rule.wg[i] * rule.wg[j] * f;
      }
    return Rect{x0, x1, y0, y1, hx * hy * k, hx * hy * std::abs(k - g)};
  };
  std::priority_queue<Rect> heap;
  heap.push(make(0.0, X, 0.0, Y));
  Estimate total{heap.top().value, heap.top().error};
  int count = 1;
  const double min_width = 1e-15 * std::min(X, Y);
  while (count < max_rectangles && total.error > tol * std::abs(total.value)) {
    const Rect r = heap.top();
    // Below 1e-15 of the cell the nodes of the corner rectangle round onto k = 0 (H = inf).
    if (r.x1 - r.x0 < min_width || r.y1 - r.y0 < min_width) break;
    heap.pop();
    const double xm = 0.5 * (r.x0 + r.x1), ym = 0.5 * (r.y0 + r.y1);
    total.value -= r.value;
    total.error -= r.error;
    for (const Rect& c : {make(r.x0, xm, r.y0, ym), make(xm, r.x1, r.y0, ym),
                          make(r.x0, xm, ym, r.y1), make(xm, r.x1, ym, r.y1)}) {
      heap.push(c);
      total.value += c.value;
      total.error += c.error;
    }
    count += 3;
  }
  total = Estimate{};
  while (!heap.empty()) {  // re-sum to shed the rounding of the running updates
    total.value += heap.top().value;
    total.error += heap.top().error;
    heap.pop();
  }
  return total;
}

}  // namespace

std::string_view to_string(G0Method method) {
  switch (method) {
    case G0Method::regularized:
      return "regularized";
    case G0Method::quadrature:
      return "quadrature";
  }
  return "unknown";
}

double mean_inverse_wavenumber(double dkx, double dky) {
  COATFFT_REQUIRE(std::isfinite(dkx) && dkx > 0, "mean_inverse_wavenumber: dkx = ", dkx,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dky) && dky > 0, "mean_inverse_wavenumber: dky = ", dky,
                  " rad/m, but it must be finite and > 0");
  return 2.0 / dky * std::asinh(dky / dkx) + 2.0 / dkx * std::asinh(dkx / dky);
}

G0Result compute_g0(const Frf& frf, double dkx, double dky, G0Method method, double tolerance) {
  COATFFT_REQUIRE(std::isfinite(dkx) && dkx > 0, "compute_g0: dkx = ", dkx,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(dky) && dky > 0, "compute_g0: dky = ", dky,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(tolerance) && tolerance > 0, "compute_g0: tolerance = ", tolerance,
                  ", but it must be finite and > 0");
  const auto start = std::chrono::steady_clock::now();
  const double area = dkx * dky;
  const double X = 0.5 * dkx, Y = 0.5 * dky;
  G0Result result{0.0, method, 0.0, 0.0};
  if (method == G0Method::regularized) {
    const double singular = frf.c0() * mean_inverse_wavenumber(dkx, dky);
    // The remainder is judged against the whole g(0): its own size can be ~0 (homogeneous body,
    // where it is pure rounding noise), so a relative tolerance on it would never be met.
    const Estimate r = remainder_integral(frf, X, Y, tolerance * std::abs(singular) * area);
    result.value = singular + r.value / area;
    result.estimated_error = r.error / area;
  } else {
    const Estimate q = quadrature_integral(frf, X, Y, tolerance);
    result.value = 4.0 * q.value / area;
    result.estimated_error = 4.0 * q.error / area;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  COATFFT_REQUIRE(std::isfinite(result.value), "compute_g0: g(0) = ", result.value, " for FRF '",
                  frf.name(), "' (method ", to_string(method),
                  "): the FRF is not finite on the "
                  "central frequency cell");
  return result;
}

}  // namespace coatfft
