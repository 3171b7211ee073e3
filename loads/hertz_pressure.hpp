#pragma once
// Hertz (ellipsoidal) pressure of a circular contact centred on the grid origin.
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "sampling.hpp"

namespace coatfft {

/// p(r) = p0 sqrt(1 - r^2/a^2) for r < a, 0 outside [Pa]; total load P = (2/3) pi a^2 p0 [N].
/// p0: peak pressure [Pa], finite; a: contact radius [m], finite and > 0. With
/// Sampling::cell_average each value is the mean over its cell (the y integral in closed form, the
/// x integral by tanh-sinh quadrature split where the circle cuts the cell, relative accuracy
/// ~1e-14), so cells cut by the circle carry exactly their share of the load.
Field hertz_pressure(const Grid& grid, double p0, double a, Sampling sampling);

/// Rows [y0, y0 + rows) of hertz_pressure(grid, p0, a, sampling), the same values: a distributed
/// rank's slab (nx, rows). Throws InvalidArgument as hertz_pressure, or for rows outside the grid.
Field hertz_pressure_rows(const Grid& grid, double p0, double a, Sampling sampling,
                          std::ptrdiff_t y0, std::ptrdiff_t rows);

}  // namespace coatfft
