#pragma once
// Cell-integrated kernels of the angular surface FRFs of docs/theory.md 2.9: the space kernels of
// cos(2 theta) exp(-beta k)/k, sin(2 theta) exp(-beta k)/k and -i cos(theta) exp(-beta k)/k
// (theta the direction of the wavevector), integrated over a dx x dy cell. With
// R = sqrt(r^2 + beta^2) they are
//   cos 2theta: (y^2 - x^2) / (2 pi R (R + beta)^2) = (1/2pi) (d_xx - d_yy) psi,
//   sin 2theta: -x y / (pi R (R + beta)^2)          = (1/pi) d_xy psi,
//   -i cos theta: x / (2 pi R (R + beta))           = (1/2pi) d_x ln(R + beta),
// psi = R - beta ln(R + beta), so that each cell integral is a corner sum of a first antiderivative
// (docs/theory.md (2.9.3)). beta = 0 gives the kernels of the homogeneous half-space's in-plane
// and coupling terms, beta > 0 the smooth transition of a layered body between its top coating
// and its substrate.
namespace coatfft {

struct AngularCoefficients {
  double cos2 = 0.0;  ///< of cos(2 theta) exp(-beta k)/k [-], even in x and y
  double sin2 = 0.0;  ///< of sin(2 theta) exp(-beta k)/k [-], odd in x and y
  double cos1 = 0.0;  ///< of -i cos(theta) exp(-beta k)/k [-], odd in x, even in y
};

/// The three cell integrals [m] at the field point (x, y) [m] of the dx x dy cell centred at the
/// origin, per unit FRF coefficient (a coefficient c [1/Pa] of exp(-beta k)/k gives c times them
/// in m/Pa). Closed forms where
/// x^2 + y^2 + beta^2 < (8 max(dx, dy))^2; beyond, where the corner sums cancel and the kernels are
/// analytic over the cell, an n x n Gauss-Legendre rule (n = 6..2 falling with the distance, as for
/// Cerruti's coefficients). Throws InvalidArgument unless dx, dy > 0, beta >= 0 and all finite.
AngularCoefficients angular_influence(double x, double y, double dx, double dy, double beta);

/// The same for the FRFs without the 1/k, cos(2 theta) exp(-beta k), sin(2 theta) exp(-beta k) and
/// -i cos(theta) exp(-beta k) (docs/theory.md (2.9.6)): the kernels
///   (y^2 - x^2)(2R + beta)/(2 pi R^3 (R + beta)^2) = (1/2pi)(d_xx - d_yy) ln(R + beta),
///   -x y (2R + beta)/(pi R^3 (R + beta)^2)          = (1/pi) d_xy ln(R + beta),
///   x/(2 pi R^3)                                    = -(1/2pi) d_x (1/R),
/// whose cell integrals [-] are corner sums of atan(X Y (R - beta)/(X^2 R + Y^2 beta)),
/// ln(R + beta) and asinh(Y/sqrt(X^2 + beta^2)). A coefficient c [m/Pa] gives c times them in m/Pa.
/// They carry the k -> 0 limit of a bounded angular FRF. The same switch to Gauss-Legendre rules;
/// InvalidArgument unless dx, dy, beta > 0 and all finite.
AngularCoefficients angular_flat_influence(double x, double y, double dx, double dy, double beta);

}  // namespace coatfft
