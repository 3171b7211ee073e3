#pragma once
// Closed-form stresses anywhere in a homogeneous half-space under a sliding Hertz contact: the
// full-field reference of the stress pipelines. Normal part: Huber (1904), in the Cartesian form
// of Hamilton & Goodman (1966) and Hamilton (1983); tangential part: Hamilton (1983).

namespace coatfft {

/// Cartesian stresses [Pa], tension positive, z into the body.
struct StressTensor {
  double xx, yy, zz, yz, xz, xy;
};

/// Stresses at (x, y, z), z >= 0 [m], under the Hertz pressure of peak p0 [Pa] and radius a [m]
/// plus a sliding traction q_x = friction * p (Hamilton 1983), on a homogeneous half-space of
/// Poisson's ratio nu. The traction acts on the body in +x: at the surface sigma_zz = -p and
/// sigma_xz = -friction p. Finite everywhere: on the axis (r = 0) the value is the limit r -> 0, at
/// z = 0 the surface value (continuous at the contact edge r = a, where it is the limit). Accuracy
/// ~1e-13 of p0 (1 + |friction|). Throws InvalidArgument on bad arguments (a <= 0, z < 0, nu
/// outside
/// (-1, 0.5], any argument not finite).
StressTensor hertz_sliding_stress(double x, double y, double z, double p0, double a, double nu,
                                  double friction);

}  // namespace coatfft
