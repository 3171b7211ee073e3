#pragma once

// Cerruti's (1882) influence coefficients of a uniformly sheared rectangle on a homogeneous
// half-space: the tangential-load counterpart of Love's coefficient (docs/theory.md section 1.3b;
// Johnson 1985, section 3.3; Love 1929).

#include "../../materials/material.hpp"

namespace coatfft {

/// Surface displacements [m] at (x, y) [m] due to a unit uniform tangential traction q_x = 1 Pa
/// (acting on the body in +x) on the dx x dy rectangle [m] centred at the origin. z is into the
/// body (docs/theory.md section 0).
///   xx: u_x, even in x and in y;  yx: u_y, odd in x and in y;  zx: u_z, odd in x, even in y
/// (zx > 0 ahead of the load: the surface there moves into the body). The coefficients of q_y
/// follow by swapping the axes: yy(x, y, dx, dy) = xx(y, x, dy, dx), xy = yx (the same function),
/// zy(x, y, dx, dy) = zx(y, x, dy, dx). By reciprocity the in-plane displacement under a unit
/// uniform pressure on the same cell is u_x = -zx(x, y), u_y = -zy(x, y) (docs/theory.md (1.5e)).
struct CerrutiCoefficients {
  double xx = 0.0;  ///< u_x per unit q_x [m/Pa]
  double yx = 0.0;  ///< u_y per unit q_x [m/Pa]
  double zx = 0.0;  ///< u_z per unit q_x [m/Pa]
};

/// The closed forms of docs/theory.md (1.5b)-(1.5d): corner sums of asinh, atan2 and log1p
/// antiderivatives written so that no term cancels near the cell's edges, corners or centre.
/// Beyond 8 max(dx, dy) from the centre, where the corner sums of xx and zx cancel, an n x n
/// Gauss-Legendre rule of the point-force kernels is used (n = 6..2, falling with the distance;
/// exact to rounding, <= 6.3e-16 relative measured); yx is evaluated in a form without
/// cancellation everywhere. The symmetries
/// above hold exactly (bit for bit). Throws InvalidArgument unless dx, dy > 0 and x, y are
/// finite.
CerrutiCoefficients cerruti_influence(double x, double y, double dx, double dy,
                                      const Material& material);

}  // namespace coatfft
