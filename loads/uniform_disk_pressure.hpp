#pragma once
// Uniform pressure on a disk centred on the grid origin (flat-ended load, Johnson §3.4).
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "sampling.hpp"

namespace coatfft {

/// p(r) = p for r < a, 0 outside [Pa]; total load P = pi a^2 p [N]. p: pressure [Pa], finite;
/// a: disk radius [m], finite and > 0. With Sampling::cell_average each value is p times the
/// exact (closed-form) fraction of the cell covered by the disk. With Sampling::centre a cell
/// whose centre lies exactly on the circle gets p / 2 (the mean of the one-sided limits).
Field uniform_disk_pressure(const Grid& grid, double p, double a, Sampling sampling);

/// Rows [y0, y0 + rows) of uniform_disk_pressure(grid, p, a, sampling), the same values: a
/// distributed rank's slab (nx, rows). Throws InvalidArgument as uniform_disk_pressure, or for
/// rows outside the grid.
Field uniform_disk_pressure_rows(const Grid& grid, double p, double a, Sampling sampling,
                                 std::ptrdiff_t y0, std::ptrdiff_t rows);

}  // namespace coatfft
