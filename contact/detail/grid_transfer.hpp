#pragma once
// Fields between a grid and the grid with half the cells per side (same lx, ly), for the nested
// start of the contact solver: the transfers of the Galerkin coarse operator R K P
// (convolution/kernels/detail/coarse_kernel.hpp).
#include "../../core/types.hpp"

namespace coatfft::detail {

/// R: the mean of each 2 x 2 block of cells, (nx, ny) even -> (nx / 2, ny / 2).
Field restrict_by_mean(const Field& fine);

/// P: each coarse cell's value on its 2 x 2 fine cells, (nx, ny) -> (2 nx, 2 ny). A pressure
/// keeps its total force.
Field prolong_by_cell(const Field& coarse);

}  // namespace coatfft::detail
