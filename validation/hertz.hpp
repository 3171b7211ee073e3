#pragma once
// Closed-form surface displacements of a homogeneous half-space under axisymmetric pressures: the
// analytic references of the DC-FFT and spectral validations (docs/theory.md sections 1.4-1.5).
#include "../core/grid.hpp"
#include "../core/types.hpp"

namespace coatfft {

/// Surface normal displacement u_z(r) [m] under the Hertz pressure p = p0 sqrt(1 - r^2/a^2) on
/// r < a, at radius r >= 0 [m]; p0 [Pa], contact radius a > 0 [m], plane-strain modulus E* [Pa].
/// Inside: docs/theory.md (1.6) (Johnson eq. 3.41a); outside: (1.7), replaced by its convergent
/// series in a/r for r > 2a, where (1.7) cancels. Throws InvalidArgument on bad arguments.
double hertz_displacement(double r, double p0, double a, double plane_strain_modulus);

/// hertz_displacement at every cell centre of `grid` (the load centred on the origin), shape
/// (nx, ny) [m]: the reference field of a Hertz pressure.
Field hertz_displacement_field(const Grid& grid, double p0, double a, double plane_strain_modulus);

/// The rows y0 to y0 + rows of hertz_displacement_field, shape (nx, rows) [m]: a slab's
/// (distributed/slab.hpp).
Field hertz_displacement_rows(const Grid& grid, double p0, double a, double plane_strain_modulus,
                              std::ptrdiff_t y0, std::ptrdiff_t rows);

/// Surface normal displacement u_z(r) [m] under a uniform pressure p [Pa] on the disk r < a, at
/// radius r >= 0 [m]; docs/theory.md (1.9) with complete elliptic integrals of modulus r/a or a/r.
/// Throws InvalidArgument on bad arguments.
double uniform_disk_displacement(double r, double p, double a, double plane_strain_modulus);

/// The error measure of Spinu (2021), Fig. 2: (u_num - u_exact) / u_exact(0), the
/// pointwise error normalised by the exact rigid-body approach (centre displacement) [-].
double centre_relative_error(double u_num, double u_exact, double u_exact_centre);

}  // namespace coatfft
