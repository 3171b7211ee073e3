#pragma once
// How a continuous surface load becomes a piecewise-constant Field (one value per cell).

namespace coatfft {

/// Sampling of a continuous pressure p(x, y) [Pa] on a Grid.
enum class Sampling {
  centre,        ///< p at the cell centre (x_i, y_j): the classical DC-FFT discretisation
  cell_average,  ///< exact mean of p over the cell: the cell force divided by dx dy, so the total
                 ///< load sum(p) dx dy equals the continuous one whenever the grid covers the load
};

}  // namespace coatfft
