#pragma once
// Contact patches: the connected pieces of a set of cells (4-neighbours: cells sharing an edge),
// across the period's border on a periodic grid.
#include <Eigen/Core>

namespace coatfft::detail {

class SolverRanks;

using CellMask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

/// The number of patches of the cells set in `cells` (a flood fill, linear in the cells). With
/// `ranks`, `cells` is this rank's rows and the count is the whole grid's, the same on every rank
/// (collective).
int count_patches(const CellMask& cells, bool periodic, const SolverRanks* ranks = nullptr);

}  // namespace coatfft::detail
