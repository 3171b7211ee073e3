#pragma once
// Removing a measured topography's mean or best plane (its tilt on the instrument's stage), and
// the gap a rigid flat sees against it (docs/surfaces.md, "Measured topographies").
#include <string_view>

#include "../core/grid.hpp"
#include "../core/types.hpp"

namespace coatfft {

enum class Detrend { none, mean, plane };

/// "none", "mean" or "plane"; InvalidArgument naming `what` otherwise.
Detrend detrend_from_name(std::string_view name, std::string_view what);

/// `heights` (nx, ny) [m] of `grid` less its mean, or less its least-squares plane
/// a + b x + c y over the cell centres (x, y of Grid::x, Grid::y), or as it is.
Field detrended(const Grid& grid, const Field& heights, Detrend detrend);

/// The gap [m] between a rigid flat and a surface of heights z (peaks up, towards the flat):
/// max(z) - z, 0 at the highest peak, which touches first.
Field gap_of_topography(const Field& heights);

}  // namespace coatfft
