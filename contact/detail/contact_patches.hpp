#pragma once
// Contact patches: the connected pieces of a set of cells (4-neighbours: cells sharing an edge),
// across the period's border on a periodic grid.
#include <Eigen/Core>

namespace coatfft::detail {

using CellMask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

/// The number of patches of the cells set in `cells` (a flood fill, linear in the cells).
int count_patches(const CellMask& cells, bool periodic);

}  // namespace coatfft::detail
