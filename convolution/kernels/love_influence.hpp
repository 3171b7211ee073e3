#pragma once
#include <cstddef>

// Love's (1929) influence coefficient of a uniformly loaded rectangle on a homogeneous half-space:
// the space-domain kernel of DC-FFT (docs/theory.md section 1.3, Johnson eq. 3.25).

namespace coatfft {

/// Surface normal displacement [m] at (x, y) [m] due to a unit uniform pressure (1 Pa) on the
/// dx x dy rectangle [m] centred at the origin, for E* = 1 Pa (divide by E* for a real material).
/// Asinh form (docs/theory.md (1.5)):
/// u = 1/pi [F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b)], a = dx/2, b = dy/2,
/// F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|). Beyond 8 max(dx, dy) from the centre, where that sum
/// cancels, an n x n Gauss-Legendre rule of 1/(pi R) is used, n = 6..2
/// falling with the distance so that it stays exact to rounding (~1e-16 relative). Throws
/// InvalidArgument unless dx, dy > 0 and x, y are finite.
double love_influence(double x, double y, double dx, double dy);

namespace detail {
/// out[i] = love_influence(i dx, y, dx, dy) [m] for i = 0..count-1 (the same rules and the same
/// arithmetic, bit for bit), with the quadrature vectorised along the row. Throws
/// InvalidArgument unless dx, dy > 0 and y are finite.
void love_influence_row(double y, double dx, double dy, std::ptrdiff_t count, double* out);
}  // namespace detail

}  // namespace coatfft
