#pragma once
// What `coatfft topography` prints about a topography, and the grid it is read on.
#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography.hpp"

namespace coatfft::topography {

/// The topography's grid: its size where the file carries one, else a spacing of one metre a
/// point (for detrending, which does not depend on the spacing; never for a contact).
Grid topography_grid(const Topography& topography);

/// {format, nx, ny, lx, ly, unit, periodic, missing, filled, detrend, rms_height, rms_slope, min,
/// max, metadata} of `heights` (the topography's heights as detrended by `detrend`) [m]; lx, ly
/// and rms_slope are null when the file carries no size, unit and periodic when it says nothing.
nlohmann::json topography_summary(const Topography& topography, const Field& heights,
                                  Detrend detrend);

}  // namespace coatfft::topography
