#pragma once
// Roughness parameters of a height map in the space domain (ISO 25178-2's Sq and Sdq, on the
// sampled points): for measured topographies, whose spectrum is not periodic.
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
