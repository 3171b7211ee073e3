#pragma once
// Influence coefficients of the same body on the grid with half the cells per side, for the
// coarse-to-fine start of the contact solver (docs/contact.md, "Nested start"). The coarse
// operator is the Galerkin product K_c = R K P, with P the piecewise-constant prolongation (a
// coarse cell's pressure on its 2 x 2 fine cells) and R = P^T / 4 the mean over them: the mean
// displacement of a coarse cell under a uniform pressure on another. For an offset D of coarse
// cells it sums the fine coefficients of the 4 x 4 pairs of fine cells,
//   K_c(D) = 1/4 sum_{a, b in {-1, 0, 1}} (2 - |a|) (2 - |b|) K(2 D + (a, b)),
// (2 - |a|) counting the pairs of fine cells whose offset is 2 D + a along x. Exact for any even
// kernel, half-space or coated, periodic or not; no new kernel is evaluated.
#include "../../../core/types.hpp"

namespace coatfft::detail {

/// The Galerkin coarse kernel of a periodic kernel (nx, ny), both even: (nx / 2, ny / 2), the
/// fine offsets taken modulo the period.
Field coarse_periodic_kernel(const Field& kernel);

/// The same for a kernel held in row slabs (distributed/): from the fine rows y0 .. y0 + rows - 1
/// (nx, rows), y0 and rows even, and the fine row y0 - 1 modulo ny, `before` (nx values), the
/// coarse rows y0 / 2 .. (y0 + rows) / 2 - 1 (nx / 2, rows / 2): the one row beyond the slab that
/// the sum reaches.
Field coarse_periodic_kernel_rows(const Field& rows, const double* before);

/// The Galerkin coarse quarter of a coefficient quarter (nx + 1, ny + 1) of an even kernel on a
/// grid of even nx, ny (convolution/kernels/influence_kernel.hpp): (nx / 2 + 1, ny / 2 + 1), the
/// unused entries di = nx / 2 and dj = ny / 2 zero. The offsets it needs, |2 D + a| <= nx - 1,
/// all lie in the fine quarter by the kernel's symmetry.
Field coarse_kernel_quarter(const Field& quarter);

}  // namespace coatfft::detail
