#pragma once
// Roughness parameters of a height map in the space domain (ISO 25178-2's Sq and Sdq, on the
// sampled points): for measured topographies, whose spectrum is not periodic. Each is computed on
// the heights divided by a power of two near the largest, so that it is finite whenever its value
// is (heights near the largest double square to infinity otherwise).
#include "../core/grid.hpp"
#include "../core/types.hpp"

namespace coatfft {

/// sqrt(mean((z - mean z)^2)) [m]: the rms height about the mean (Sq).
double rms_height(const Field& heights);

/// sqrt(mean (dz/dx)^2 + mean (dz/dy)^2) [-] by differences of neighbouring points over the
/// grid's spacing (Sdq on the sampled points): across the edges too when `periodic`, else
/// between points of the map only.
double rms_slope(const Grid& grid, const Field& heights, bool periodic);

}  // namespace coatfft

namespace coatfft {

/// How far a map is from joining its own copies when it is taken as periodic: the rms height
/// jump between opposite edges (z(0, j) - z(nx - 1, j) and z(i, 0) - z(i, ny - 1)) [m], and the
/// rms step between neighbours inside the map [m], its scale. A ratio near 1 joins seamlessly;
/// far above 1 the periodic copies meet at a cliff (docs/measured_surfaces.md).
struct EdgeMismatch {
  double rms_jump = 0.0;
  double rms_step = 0.0;
};
EdgeMismatch edge_mismatch(const Field& heights);

}  // namespace coatfft
