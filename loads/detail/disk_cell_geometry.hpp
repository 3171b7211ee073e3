#pragma once
// Geometry shared by the disk-supported loads: where a circle of radius 1 cuts a cell, in
// coordinates scaled by the load radius. Internal to loads/.
#include <vector>

namespace coatfft::detail {

/// A cell [x0, x1] x [y0, y1] in units of the load radius.
struct ScaledCell {
  double x0, x1, y0, y1;
};

/// Distances from the origin to the nearest and the farthest point of the cell.
double min_radius(const ScaledCell& c);
double max_radius(const ScaledCell& c);

/// The x-interval of the cell clipped to [-1, 1], split at every x where the half-chord
/// c(x) = sqrt(1 - x^2) crosses |y0| or |y1|: on each piece the clipped chord
/// [max(y0, -c), min(y1, c)] keeps the same form, so integrands are smooth inside a piece.
/// Returns the sorted breakpoints (first and last are the interval ends); empty if none.
std::vector<double> chord_breakpoints(const ScaledCell& c);

}  // namespace coatfft::detail
