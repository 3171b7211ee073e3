#include "validation/hankel_displacement.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <memory>
#include <numbers>

#include "core/detail/gsl_quadrature.hpp"
#include "core/error.hpp"
#include "validation/hertz.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

constexpr std::size_t kLimit = 1000;

// Adaptive Gauss-Kronrod (21 points) on [lo, hi]; the nodes are interior, so k = 0 is never hit.
double integrate_panel(const std::function<double(double)>& f, double lo, double hi, double epsabs,
                       double epsrel, gsl_integration_workspace* ws) {
  const detail::GslIntegral r = detail::gsl_qag(f, lo, hi, epsabs, epsrel, GSL_INTEG_GAUSS21, ws);
  const int status = r.status;
  const double result = r.value, abserr = r.error;
  // GSL_EROUND means the requested tolerance is below the attainable rounding: keep the result if
  // its error estimate is still within a generous multiple of the request.
  if (status != GSL_SUCCESS &&
      !(status == GSL_EROUND && abserr <= 100.0 * std::max(epsabs, epsrel * std::abs(result)))) {
    throw Error(detail::concat("hankel_displacement: quadrature on [", lo, ", ", hi,
                               "] rad/m failed (", gsl_strerror(status), ", error ", abserr, ")"));
  }
  return result;
}

// Smallest K (a power-of-two multiple of 1e-3/a) from which k H(k) = c_inf to `threshold`
// relative over 8 consecutive doublings: beyond it, H - c_inf/k is negligible. Coated and layered
// FRFs converge like (kh)^2 exp(-2 k h_top) (docs/theory.md §2.2), so K ~ 20/h_top.
double converged_wavenumber(const Frf& frf, double a, double threshold) {
  const double c_inf = frf.c_inf();
  int run = 0;
  double start = 0.0;
  double k = 1e-3 / a;
  for (int j = 0; j < 400; ++j, k *= 2.0) {
    if (std::abs(k * frf(k) / c_inf - 1.0) <= threshold) {
      if (run == 0) start = k;
      if (++run == 8) return start;
    } else {
      run = 0;
    }
  }
  throw Error(detail::concat("hankel_displacement: k H(k) of FRF \"", frf.name(),
                             "\" does not approach c_inf() = ", c_inf, " as k grows"));
}

// \int_lo^hi f dk on panels no wider than a half period of the fastest oscillation of
// Phi(ka) J0(kr), i.e. pi/(a + r).
double integrate_panels(const std::function<double(double)>& f, double hi, double a, double r,
                        double epsabs_total, double epsrel, gsl_integration_workspace* ws) {
  const double width = pi / (a + r);
  const auto nb = static_cast<long>(std::ceil(hi / width));
  const double epsabs = epsabs_total / static_cast<double>(nb);
  double sum = 0.0;
  for (long i = 0; i < nb; ++i) {
    const double lo = static_cast<double>(i) * width;
    sum += integrate_panel(f, lo, std::min(hi, lo + width), epsabs, epsrel, ws);
  }
  return sum;
}

// Hankel asymptotic expansion of J_nu(x) = sqrt(2/(pi x)) Re[(P + iQ) exp(i(x - nu pi/2 - pi/4))]
// (DLMF 10.17.3), with 8 terms: at x >= 500 the first omitted term is < 1e-20 relative.
std::complex<double> hankel_pq(int nu, double x) {
  const double mu = 4.0 * nu * nu;
  double coef = 1.0;  // a_k(nu) / x^k
  std::complex<double> sum = 1.0;
  for (int k = 1; k <= 8; ++k) {
    coef *= (mu - (2.0 * k - 1.0) * (2.0 * k - 1.0)) / (k * 8.0 * x);
    // P = sum (-1)^m a_2m / x^2m, Q = sum (-1)^m a_(2m+1) / x^(2m+1)
    const double sign = (k / 2) % 2 == 0 ? 1.0 : -1.0;
    if (k % 2 == 0)
      sum += sign * coef;
    else
      sum += std::complex<double>(0.0, sign * coef);
  }
  return sum;
}

// Amplitudes F, G of Phi(s) = Re[F(s) e^{is}] and J0(rho s) = Re[G(s) e^{i rho s}].
std::complex<double> shape_amplitude(AxisymmetricLoad load, double s) {
  if (load == AxisymmetricLoad::hertz) {  // (sin s - s cos s)/s^3, exact
    return {-1.0 / (s * s), -1.0 / (s * s * s)};
  }
  return std::sqrt(2.0 / (pi * s)) / s * hankel_pq(1, s) * std::polar(1.0, -0.75 * pi);
}

// J_n(rho s) = Re[G(s) e^{i rho s}] (J_n(0) = 0 for n >= 1).
std::complex<double> bessel_amplitude(int n, double rho, double s) {
  if (rho == 0.0) return n == 0 ? 1.0 : 0.0;
  const double x = rho * s;
  return std::sqrt(2.0 / (pi * x)) * hankel_pq(n, x) * std::polar(1.0, -(0.5 * n + 0.25) * pi);
}

// \int_S^inf Re[g(s) e^{i omega s}] ds for a smooth, algebraically decaying g.
double oscillatory_tail(const std::function<std::complex<double>(double)>& g, double omega,
                        double S, double epsabs) {
  const detail::GslWorkspace ws = detail::make_gsl_workspace(kLimit);
  double total = 0.0;
  if (omega == 0.0) {
    const std::function<double(double)> f = [&g](double s) { return g(s).real(); };
    gsl_function gf = detail::as_gsl_function(f);
    double result = 0.0, abserr = 0.0;
    const int status =
        gsl_integration_qagiu(&gf, S, epsabs, 0.0, kLimit, ws.get(), &result, &abserr);
    if (status != GSL_SUCCESS && !(status == GSL_EROUND && abserr <= 100.0 * epsabs)) {
      throw Error(detail::concat("hankel_displacement: tail quadrature failed (",
                                 gsl_strerror(status), ")"));
    }
    return result;
  }
  // Re[g e^{i w s}] = Re g cos(w s) - Im g sin(w s); for w < 0 use |w| and flip the sine.
  const double w = std::abs(omega);
  const double sine_sign = omega > 0 ? -1.0 : 1.0;
  const detail::GslWorkspace cycles = detail::make_gsl_workspace(kLimit);
  for (auto kind : {GSL_INTEG_COSINE, GSL_INTEG_SINE}) {
    const std::function<double(double)> f = [&g, kind, sine_sign](double s) {
      return kind == GSL_INTEG_COSINE ? g(s).real() : sine_sign * g(s).imag();
    };
    gsl_function gf = detail::as_gsl_function(f);
    gsl_integration_qawo_table* table = gsl_integration_qawo_table_alloc(w, 1.0, kind, 50);
    double result = 0.0, abserr = 0.0;
    const int status = gsl_integration_qawf(&gf, S, epsabs, kLimit, ws.get(), cycles.get(), table,
                                            &result, &abserr);
    gsl_integration_qawo_table_free(table);
    if (status != GSL_SUCCESS && !(status == GSL_EROUND && abserr <= 100.0 * epsabs)) {
      throw Error(detail::concat("hankel_displacement: oscillatory tail quadrature failed (",
                                 gsl_strerror(status), ", error ", abserr, ")"));
    }
    total += result;
  }
  return total;
}

// \int_S^inf Phi(s) J_n(rho s) ds by Phi J_n = (1/2) Re[F G e^{i(1+rho)s}] + (1/2) Re[F conj(G)
// e^{i(1-rho)s}], valid once s and rho s are in the asymptotic range.
double asymptotic_tail(int n, AxisymmetricLoad load, double rho, double S, double epsabs) {
  const auto sum_part = [n, load, rho](double s) {
    return 0.5 * shape_amplitude(load, s) * bessel_amplitude(n, rho, s);
  };
  const auto difference_part = [n, load, rho](double s) {
    return 0.5 * shape_amplitude(load, s) * std::conj(bessel_amplitude(n, rho, s));
  };
  return oscillatory_tail(sum_part, 1.0 + rho, S, 0.5 * epsabs) +
         oscillatory_tail(difference_part, 1.0 - rho, S, 0.5 * epsabs);
}

// The most panels one call integrates (each an adaptive 21-point rule, ~(a + r) K / pi of them
// resolve J0(kr) up to K): seconds of FRF calls. Beyond, the far field is used or r is
// refused (far_field).
constexpr double kMaxPanels = 1 << 20;

double panel_count(double hi, double a, double r) {
  return std::ceil(hi * (a + r) / pi);
}

// k H(k) = c0 + d1 k + d2 k^2 + d3 k^3 + ... near k = 0, from three samples at k_s/4, k_s/2, k_s,
// k_s the largest k of 8 consecutive halvings from k_max with |k H/c0 - 1| <= 1e-4 (well inside
// the series' range). Returns k_s and a bound on |d2|: the fitted value, the next term's share
// at k_s and the rounding of k H (1e-15 relative) divided by k^2.
struct SmallWavenumbers {
  double k_s, d2_bound;
};

SmallWavenumbers second_order_bound(const Frf& frf, double k_max) {
  const double c0 = frf.c0();
  const auto q = [&](double k) { return (k * frf(k) - c0) / k; };
  int run = 0;
  double k_s = 0.0;
  for (double k = k_max; run < 8; k *= 0.5) {
    if (k < 1e-280 * k_max)
      throw Error(detail::concat("hankel_displacement: k H(k) of FRF \"", frf.name(),
                                 "\" does not approach c0() = ", c0, " as k -> 0"));
    if (std::abs(k * frf(k) / c0 - 1.0) <= 1e-4) {
      if (run++ == 0) k_s = k;
    } else {
      run = 0;
    }
  }
  const double k1 = 0.25 * k_s, k2 = 0.5 * k_s, k3 = k_s;
  const double q1 = q(k1), q2 = q(k2), q3 = q(k3);
  const double q12 = (q2 - q1) / (k2 - k1), q23 = (q3 - q2) / (k3 - k2);
  const double d3 = (q23 - q12) / (k3 - k1);
  const double d2 = q12 - d3 * (k1 + k2);
  return {k_s, std::abs(d2) + std::abs(d3) * k_s + 1e-15 * c0 * 64.0 / (k_s * k_s)};
}

// u_z at an r too large for the panels (panel_count > kMaxPanels). Outside the load the odd powers
// of k in k H Phi(ka) contribute nothing (k^(2m+1) Phi(ka) transforms to a derivative of the
// pressure, 0 for r > a) and the even ones k^(2m) like r^-(2m+1): u_z is the half-space of
// compliance c0 (E* = 2/c0) under the same load, within a relative d2/(c0 r^2). That is returned
// where it is below rel_tol/10 (and r >= 100/k_s, where the series holds, and r >= 10 a, where
// the k^2 term's field is that of a point force); otherwise r is refused.
double far_field(const Frf& frf, AxisymmetricLoad load, double amplitude, double a, double r,
                 double rel_tol, double k_max) {
  const double c0 = frf.c0();
  const SmallWavenumbers small = second_order_bound(frf, k_max);
  const double r_far =
      std::max({std::sqrt(10.0 * small.d2_bound / (rel_tol * c0)), 100.0 / small.k_s, 10.0 * a});
  const double r_quadrature = pi * kMaxPanels / k_max - a;
  COATFFT_REQUIRE(r >= r_far, "hankel_displacement: r = ", r, " m is beyond the ", r_quadrature,
                  " m the quadrature resolves for FRF \"", frf.name(), "\" and short of the ",
                  r_far, " m from which its far field holds to rel_tol = ", rel_tol);
  const double e_star = 2.0 / c0;
  return load == AxisymmetricLoad::hertz ? hertz_displacement(r, amplitude, a, e_star)
                                         : uniform_disk_displacement(r, amplitude, a, e_star);
}

}  // namespace

double hankel_displacement(const Frf& frf, AxisymmetricLoad load, double amplitude, double a,
                           double r, double rel_tol, HankelRoute route) {
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "hankel_displacement: a = ", a,
                  " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(r) && r >= 0, "hankel_displacement: r = ", r,
                  " m, but r must be finite and >= 0");
  COATFFT_REQUIRE(std::isfinite(amplitude), "hankel_displacement: amplitude = ", amplitude,
                  " Pa, but it must be finite");
  COATFFT_REQUIRE(rel_tol >= 1e-14 && rel_tol < 1e-2, "hankel_displacement: rel_tol = ", rel_tol,
                  ", but it must lie in [1e-14, 1e-2)");
  const detail::GslHandlerOff handler_off;
  const detail::GslWorkspace ws = detail::make_gsl_workspace(kLimit);
  const double c_inf = frf.c_inf();
  // u ~ amplitude a C: the dimensionless integrals below are O(max(C0, Cinf)/a) or O(1).
  const double scale = std::max(frf.c0(), c_inf) / a;
  const double k_converged = converged_wavenumber(frf, a, 1e-3 * rel_tol);
  // The direct route's panels reach max(k_converged, 500/min(a, r)) (hankel_load_integral).
  const double k_max = route == HankelRoute::split
                           ? k_converged
                           : std::max(k_converged, 500.0 / std::min(a, r > 0 ? r : a));
  if (panel_count(k_max, a, r) > kMaxPanels)
    return far_field(frf, load, amplitude, a, r, rel_tol, k_max);
  // u = amplitude a^2 \int_0^inf k H(k) Phi(ka) J0(kr) dk (the 2 pi of P^ cancels the 1/2pi).
  if (route == HankelRoute::split) {
    const std::function<double(double)> remainder = [&](double k) {
      return (k * frf(k) - c_inf) * axisymmetric_load_shape(load, k * a) * gsl_sf_bessel_J0(k * r);
    };
    const double rest = integrate_panels(remainder, k_converged, a, r, 1e-2 * rel_tol * scale,
                                         1e-2 * rel_tol, ws.get());
    const double e_star_top = 2.0 / c_inf;
    const double homogeneous = load == AxisymmetricLoad::hertz
                                   ? hertz_displacement(r, amplitude, a, e_star_top)
                                   : uniform_disk_displacement(r, amplitude, a, e_star_top);
    return homogeneous + amplitude * a * a * rest;
  }
  // Direct: beyond k_converged k H = c_inf (to 1e-3 rel_tol).
  return hankel_load_integral([&frf](double k) { return k * frf(k); }, c_inf, k_converged, 0, load,
                              amplitude, a, r, scale, rel_tol);
}

double hankel_load_integral(const std::function<double(double)>& g, double g_inf,
                            double k_converged, int order, AxisymmetricLoad load, double amplitude,
                            double a, double r, double scale, double rel_tol) {
  COATFFT_REQUIRE(order >= 0 && order <= 2, "hankel_load_integral: order ", order,
                  " is not 0, 1 or 2");
  const detail::GslHandlerOff handler_off;
  const detail::GslWorkspace ws = detail::make_gsl_workspace(kLimit);
  // Beyond K both g = g_inf and the Hankel expansions hold (k a >= 500 and k r >= 500, where 8
  // terms are exact to double precision).
  const double rho = r / a;
  const double K = std::max(k_converged, 500.0 / a * (rho > 0 ? std::max(1.0, 1.0 / rho) : 1.0));
  const std::function<double(double)> full = [&](double k) {
    return g(k) * axisymmetric_load_shape(load, k * a) * gsl_sf_bessel_Jn(order, k * r);
  };
  const double head =
      integrate_panels(full, K, a, r, 1e-2 * rel_tol * scale, 1e-2 * rel_tol, ws.get());
  // \int_K^inf Phi(ka) J_n(kr) dk = (1/a) \int_{Ka}^inf Phi(s) J_n(rho s) ds.
  const double tail = g_inf / a * asymptotic_tail(order, load, rho, K * a, 1e-3 * rel_tol);
  return amplitude * a * a * (head + tail);
}

}  // namespace coatfft
