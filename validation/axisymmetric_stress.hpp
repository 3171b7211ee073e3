#pragma once
// Continuous reference for the stresses and displacements at depth of any layer stack under an
// axisymmetric surface pressure: Hankel integrals of the real mode coefficients of
// docs/theory.md 2.7 (LayerModes). With P^(k) = 2 pi \int_0^a p(s) J0(k s) s ds (section 0) and
// Delta = sLL_p - sTT_p,
//   sigma_zz = (1/2pi) \int szz_p P^ J0(kr) k dk       u_z = (1/2pi) \int uz_p P^ J0(kr) k dk
//   tau_rz   = -(1/2pi) \int sLz_p P^ J1(kr) k dk      u_r = -(1/2pi) \int uL_p P^ J1(kr) k dk
//   sigma_rr = (1/2pi) \int [sLL_p J0(kr) - Delta J1(kr)/(kr)] P^ k dk
//   sigma_tt = (1/2pi) \int [sTT_p J0(kr) + Delta J1(kr)/(kr)] P^ k dk
// (u_L = i uL_p and sigma_Lz = i sLz_p turn into the gradient of an order-0 transform, whence the
// minus signs and J1; the in-plane stress sTT delta_ij + Delta k^_i k^_j into the second
// derivatives of one). It checks the stress pipelines of coated and layered bodies, where no
// closed form exists.
#include <span>
#include <vector>

#include "../frf/layer_modes.hpp"
#include "../layers/layer_stack.hpp"
#include "hankel_displacement.hpp"

namespace coatfft {

/// Stresses [Pa] and displacements [m] at (r, z) of an axisymmetric field; cylindrical components,
/// tension positive, z into the body, srz = tau_rz.
struct AxisymmetricStress {
  double srr, stt, szz, srz, ur, uz;
};

/// The fields at radius r >= 0 [m] and depth z > 0 [m] under the load of `amplitude` [Pa] (p0 or
/// p, compressive when > 0) and radius a > 0 [m] on the body of `stack`, by the Hankel integrals
/// above: panel Gauss-Kronrod (7-15) quadrature up to k z ~ 40-60, with panels no wider than a
/// quarter period of the oscillation of J(kr) P^(k), 1/(4 h_min) and 1/z, bisected where the
/// Kronrod-Gauss difference asks for it. Accuracy ~rel_tol (1e-14 <= rel_tol < 1e-2) of
/// |amplitude| for the stresses and of |amplitude| a / mu_min (softest medium) for the
/// displacements. A depth on an interface (LayerStack::locate) is taken in the medium `side`
/// names. z = 0 is refused: the integrals converge there only conditionally (the surface stresses
/// jump at r = a under a uniform disk). Throws InvalidArgument on bad arguments, Error when the
/// quadrature fails. Cost ~50 max(0.64 (r + a), 4 h_min, z)/z panels of 15 LayerModes solves (0.2 s
/// at r = 3a, z = 0.01a).
AxisymmetricStress axisymmetric_stress(const LayerStack& stack, AxisymmetricLoad load,
                                       double amplitude, double a, double r, double z,
                                       InterfaceSide side = InterfaceSide::below,
                                       double rel_tol = 1e-10);

/// The same at every radius of `r` and depth z: one LayerModes solve per wavenumber for all
/// radii (the panels follow the largest radius). Element i is the field at r[i].
std::vector<AxisymmetricStress> axisymmetric_stress_at(const LayerStack& stack,
                                                       AxisymmetricLoad load, double amplitude,
                                                       double a, std::span<const double> r,
                                                       double z,
                                                       InterfaceSide side = InterfaceSide::below,
                                                       double rel_tol = 1e-10);

/// The same on the grid of radii `r` and depths `z` (each depth > 0; the panels follow the largest
/// radius and the smallest depth). Element iz * r.size() + ir is the field at (r[ir], z[iz]).
std::vector<AxisymmetricStress> axisymmetric_stress_grid(const LayerStack& stack,
                                                         AxisymmetricLoad load, double amplitude,
                                                         double a, std::span<const double> r,
                                                         std::span<const double> z,
                                                         InterfaceSide side = InterfaceSide::below,
                                                         double rel_tol = 1e-10);

}  // namespace coatfft
