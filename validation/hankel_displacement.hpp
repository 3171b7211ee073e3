#pragma once
// Continuous reference for any FRF under an axisymmetric surface pressure: the surface normal
// displacement as a Hankel integral (docs/theory.md §0, §1.4-1.5),
//   u_z(r) = (1/2pi) \int_0^inf H(k) P^(k) J0(k r) k dk,   P^(k) = 2 pi \int_0^a p(s) J0(k s) s ds.
// It checks FFT pipelines for coated and layered bodies, where no closed form exists.
#include <functional>

#include "../frf/frf.hpp"
#include "../loads/axisymmetric_load.hpp"

namespace coatfft {

/// How the Hankel integral is evaluated (both target the same rel_tol).
enum class HankelRoute {
  /// H = c_inf/k + (H - c_inf/k): the first part in closed form (docs/theory.md (1.6)-(1.9) with
  /// E* = 2/c_inf), the remainder, which decays like exp(-2 k h_top), by panel quadrature on a
  /// finite range. Fast and accurate; the default.
  split,
  /// The full integrand by panel quadrature up to a large K, plus the tail beyond K from the
  /// Hankel asymptotic expansions of the load transform and J0 (GSL qawf). Slower; an
  /// independent cross-check of `split` that does not use the homogeneous closed forms.
  direct,
};

/// u_z(r) [m] at radius r >= 0 [m] for the load of `amplitude` [Pa] and radius a > 0 [m] on the
/// body of FRF `frf`, to relative accuracy ~rel_tol (1e-14 <= rel_tol < 1e-2). Throws
/// InvalidArgument on bad arguments and Error when the quadrature fails to reach the tolerance.
/// Cost: ~(a + r)/h_top quadrature panels of 21 FRF calls (split route); safe to call from
/// several threads at once (GSL's error handler is switched off for the duration, ref-counted).
/// Where more than 2^20 panels would be needed, the far field: the half-space of compliance
/// c0 under the same load (E* = 2/c0), whose relative error d2/(c0 r^2) (d2 the k^2 coefficient
/// of k H near k = 0, fitted from three samples) must be below rel_tol/10, else InvalidArgument
/// naming r and both distances. Finite for every finite r.
double hankel_displacement(const Frf& frf, AxisymmetricLoad load, double amplitude, double a,
                           double r, double rel_tol = 1e-10,
                           HankelRoute route = HankelRoute::split);

/// amplitude a^2 \int_0^inf g(k) Phi(ka) J_n(kr) dk, n = `order` in {0, 1, 2}, Phi the load's shape
/// (P^(k) = 2 pi amplitude a^2 Phi(ka)): hankel_displacement's direct route for any g that equals
/// g_inf [m/Pa] beyond k_converged [rad/m] to 1e-3 rel_tol (g = k H for u_z; the other orders give
/// the in-plane and coupling displacements of docs/theory.md 2.9). Panels up to K =
/// max(k_converged, 500/min(a, r)), the tail beyond from the Hankel expansions (GSL QAWF). `scale`
/// [m/Pa / m] sets the absolute tolerance rel_tol scale of the head. InvalidArgument for another
/// order, Error when a quadrature fails.
double hankel_load_integral(const std::function<double(double)>& g, double g_inf,
                            double k_converged, int order, AxisymmetricLoad load, double amplitude,
                            double a, double r, double scale, double rel_tol);

}  // namespace coatfft
