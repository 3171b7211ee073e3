#pragma once
// Continuous reference for the 3 x 3 surface response of any bonded layer stack: the surface
// displacements under an axisymmetric load acting as a pressure or as a traction q_x, by Hankel
// integrals of the surface FRFs of docs/theory.md 2.9 (frf/traction_response.hpp). With
// Q^(k) = 2 pi \int_0^a q(s) J0(k s) s ds and the field point at (r cos phi, r sin phi):
//   under q_x:  u_x = (1/2pi) \int [S J0(kr) - D cos 2phi J2(kr)] Q^ k dk,
//               u_y = -(1/2pi) sin 2phi \int D J2(kr) Q^ k dk,
//               u_z = (1/2pi) cos phi \int C J1(kr) Q^ k dk;
//   under p:    u_x = -(1/2pi) cos phi \int C J1(kr) P^ k dk, u_y likewise with sin phi,
//               u_z = (1/2pi) \int H_zz J0(kr) P^ k dk
// (the angular factors of the FRFs turn into J_n by \int_0^2pi e^{i n theta} e^{i k r cos(theta -
// phi)} dtheta = 2 pi i^n J_n(kr) e^{i n phi}). It checks the layered traction kernels
// (convolution/kernels/traction_kernels.hpp), where no closed form exists.
#include "../layers/layer_stack.hpp"
#include "hankel_displacement.hpp"

namespace coatfft {

/// Surface displacements [m], u_z into the body.
struct SurfaceDisplacement {
  double ux = 0.0, uy = 0.0, uz = 0.0;
};

/// Which way the axisymmetric load acts.
enum class LoadDirection { pressure, traction_x };

/// The displacements at (x, y) [m] (finite; not closer than 1e-3 a to the centre unless at it)
/// under the load of shape `load`, `amplitude` [Pa] and radius a > 0 [m] acting as `direction`
/// on the bonded body `stack`, to ~rel_tol (1e-12 <= rel_tol < 1e-2) of amplitude a / mu_min.
/// InvalidArgument on bad arguments or a frictionless interface; Error when a quadrature fails.
/// Cost: about 500 (1 + r/a) / (pi min(1, r/a)) panels of 21 LayerModes solves per integral.
SurfaceDisplacement axisymmetric_surface_displacement(const LayerStack& stack,
                                                      AxisymmetricLoad load,
                                                      LoadDirection direction, double amplitude,
                                                      double a, double x, double y,
                                                      double rel_tol = 1e-10);

}  // namespace coatfft
