#pragma once
// What `coatfft topography` prints about a topography, and the grid it is read on.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "core/grid.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography.hpp"

namespace coatfft::topography {

/// The topography's grid: its size where the file carries one, else a spacing of one metre a
/// point (for detrending, which does not depend on the spacing; never for a contact). A map a grid
/// cannot hold (too many points along an axis, a size beyond Grid's lengths) is refused naming
/// `file` and what in it is wrong.
Grid topography_grid(const std::filesystem::path& file, const Topography& topography);

/// Refuses (InvalidArgument naming `file` and `what`: "the gap max(z) - z") a map made from the
/// file's heights that overflowed to an infinite or NaN value.
void require_finite_map(const std::filesystem::path& file, const Field& map, std::string_view what);

/// {format, nx, ny, lx, ly, unit, periodic, missing, detrend, rms_height, rms_slope, min, max,
/// metadata} of `heights` (the topography's heights as detrended by `detrend`) [m]. lx, ly and
/// rms_slope are those of `sized`, the grid the map is read on (across its edges when
/// `periodic`), and null without one (a file without a size); unit and periodic (the file's
/// flag) null when the file says nothing. A parameter beyond the largest double is refused
/// naming `file`.
nlohmann::json topography_summary(const std::filesystem::path& file, const Topography& topography,
                                  const Field& heights, Detrend detrend,
                                  const std::optional<Grid>& sized, bool periodic);

}  // namespace coatfft::topography
