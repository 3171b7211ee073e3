#include "convolution/kernels/g0.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "core/detail/gsl_quadrature.hpp"
#include "core/detail/parse_name.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

namespace coatfft {
namespace {

using std::numbers::pi;

struct Estimate {
  double value = 0.0;
  double error = 0.0;
};

// The QAG subdivision limit of every integral below: far more than any FRF of frf/ needs (a few
// tens of panels); when it is reached, GSL's estimate of the error is reported, not hidden.
constexpr std::size_t max_intervals = 200;

Estimate to_estimate(const detail::GslIntegral& r) {
  return {r.value, r.error};
}

// \iint_cell (H(|k|) - C0/|k|) dk for the cell [-X, X] x [-Y, Y]. For a radial integrand,
// \iint_rect f(|k|) dk = \int_0^D f(rho) rho w(rho) d rho, with w(rho) the angle of the circle of
// radius rho inside the rectangle: 2 pi for rho <= m = min(X, Y), 2 pi - 4 acos(m/rho) up to
// M = max(X, Y), then 2 pi - 4 acos(X/rho) - 4 acos(Y/rho) up to the corner D. Here
// f rho = rho H - C0 =: s(rho), bounded and smooth (docs/theory.md 3.2). The square-root kinks of w
// at m and M are removed by rho = m / cos(phi) resp. M / cos(phi), for which acos(m/rho) = phi:
// this is the polar-sector integral of docs/theory.md 3.2 with the angular integration done
// exactly.
Estimate remainder_integral(const Frf& frf, double X, double Y, double abs_tol) {
  const double c0 = frf.c0();
  const double m = std::min(X, Y), M = std::max(X, Y), D = std::hypot(X, Y);
  auto s = [&](double rho) { return rho * frf(rho) - c0; };
  // Each piece to a third of the absolute tolerance (QAG, 31-point Gauss-Kronrod): the remainder
  // can be ~0 (homogeneous body: pure rounding noise), so no relative tolerance is asked.
  const detail::GslWorkspace ws = detail::make_gsl_workspace(max_intervals);
  const auto qag = [&](const std::function<double(double)>& f, double lo, double hi) {
    return to_estimate(detail::gsl_qag(f, lo, hi, abs_tol / 3.0, 0.0, GSL_INTEG_GAUSS31, ws.get()));
  };
  // Piece A: rho in [0, m], full circle.
  Estimate a = qag([&](double rho) { return 2.0 * pi * s(rho); }, 0.0, m);
  // Piece B: rho in [m, M], circle cut by the near sides only.
  Estimate b;
  if (M > m) {
    b = qag(
        [&](double phi) {
          const double c = std::cos(phi);
          const double rho = m / c;
          return s(rho) * (2.0 * pi - 4.0 * phi) * m * std::sin(phi) / (c * c);
        },
        0.0, std::acos(m / M));
  }
  // Piece C: rho in [M, D], cut by all four sides.
  Estimate c = qag(
      [&](double phi) {
        const double cs = std::cos(phi);
        const double rho = M / cs;
        const double other = (M > m) ? std::acos(std::min(m / rho, 1.0)) : phi;
        const double w = std::max(2.0 * pi - 4.0 * phi - 4.0 * other, 0.0);
        return s(rho) * w * M * std::sin(phi) / (cs * cs);
      },
      0.0, std::acos(M / D));
  return {a.value + b.value + c.value, a.error + b.error + c.error};
}

// Plain adaptive quadrature of H over the quadrant [0, X] x [0, Y] (the cell is 4 such
// quadrants), the approach of Spinu (2021), as iterated 1-D integrals by GSL's QAGS:
// I = \int_0^Y F(ky) dky with F(ky) = \int_0^X H(hypot(kx, ky)) dkx. For ky > 0 the inner
// integrand is bounded (by ~C0/ky) but peaked at kx = 0; F has a logarithmic singularity at ky = 0
// (F ~ C0 asinh(X/ky)), which QAGS's extrapolation is made for. Neither rule evaluates an end
// point, so H(0) = inf is never called. The inner integrals get a tenth of the relative
// tolerance, so that their errors do not dominate the outer one; the reported error is the outer
// estimate plus the inner estimates integrated over ky (accumulated at the outer rule's nodes).
Estimate quadrature_integral(const Frf& frf, double X, double Y, double tol) {
  const detail::GslWorkspace outer_ws = detail::make_gsl_workspace(max_intervals);
  const detail::GslWorkspace inner_ws = detail::make_gsl_workspace(max_intervals);
  double inner_error_sum = 0.0;  // sum over outer nodes of |inner error|, for the estimate
  double inner_calls = 0.0;
  // QAGS refuses relative tolerances below 50 machine epsilons (GSL_EBADTOL): a tighter request is
  // met as far as double precision allows, and the error estimate says how far that was.
  const double floor = 50.0 * std::numeric_limits<double>::epsilon() * (1.0 + 1e-6);
  const double outer_tol = std::max(tol, floor), inner_tol = std::max(0.1 * tol, floor);
  const std::function<double(double)> inner_integral = [&](double ky) {
    const detail::GslIntegral r = detail::gsl_qags(
        [&](double kx) { return frf(std::hypot(kx, ky)); }, 0.0, X, 0.0, inner_tol, inner_ws.get());
    inner_error_sum += r.error;
    inner_calls += 1.0;
    return r.value;
  };
  const detail::GslIntegral outer =
      detail::gsl_qags(inner_integral, 0.0, Y, 0.0, outer_tol, outer_ws.get());
  // The inner errors, averaged over the outer nodes, integrated over [0, Y].
  const double inner_error = inner_calls > 0 ? Y * inner_error_sum / inner_calls : 0.0;
  return {outer.value, outer.error + inner_error};
}

}  // namespace

std::string_view to_string(G0Method method) {
  switch (method) {
    case G0Method::regularized:
      return "regularized";
    case G0Method::quadrature:
      return "quadrature";
    case G0Method::omitted:
      return "omitted";
  }
  return "unknown";
}

G0Method parse_g0_method(std::string_view name) {
  return detail::parse_name(
      name, std::array{G0Method::regularized, G0Method::quadrature, G0Method::omitted});
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
  if (method == G0Method::omitted) return result;
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
  result.seconds = detail::seconds_since(start);
  COATFFT_REQUIRE(std::isfinite(result.value), "compute_g0: g(0) = ", result.value, " for FRF '",
                  frf.name(), "' (method ", to_string(method),
                  "): the FRF is not finite on the "
                  "central frequency cell");
  return result;
}

}  // namespace coatfft
