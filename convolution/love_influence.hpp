#pragma once
// Love's (1929) influence coefficient of a uniformly loaded rectangle on a homogeneous half-space:
// the space-domain kernel of DC-FFT (theory.md section 1.3, Johnson eq. 3.25).

namespace coatfft {

/// Surface normal displacement [m] at (x, y) [m] due to a unit uniform pressure (1 Pa) on the
/// dx x dy rectangle [m] centred at the origin, for E* = 1 Pa (divide by E* for a real material).
/// Asinh form (theory.md 1.5): u = 1/pi [F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b)],
/// a = dx/2, b = dy/2, F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|). Beyond 8 max(dx, dy) from the
/// centre, where that sum cancels, a 6 x 6 Gauss-Legendre rule of 1/(pi R) is used (exact to
/// rounding there). Throws InvalidArgument unless dx, dy > 0 and x, y are finite.
double love_influence(double x, double y, double dx, double dy);

}  // namespace coatfft
