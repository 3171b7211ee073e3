#pragma once
// The readers of each topography format, for read_topography (topography.hpp) only. Each returns
// the file's content as it is: heights in the file's unit (`unit` names it, "" when the file has
// none) or already in metres where the format defines it (X3P, SDF: `unit` "m"), NaN at missing
// points (counted in `missing`), lx and ly in the same unit as the heights when the file carries
// a spacing. read_topography converts the units, fills or refuses missing points and checks the
// result.
#include <cstdint>
#include <filesystem>

#include "topography/topography.hpp"

namespace coatfft::topography {

Topography read_npy_topography(const std::filesystem::path& path, const ReadOptions& options);
/// A matrix of heights (format "csv") or "x y z" rows on a regular grid (format "xyz"; always
/// when `xyz`, else when the file's three columns make such rows).
Topography read_text_topography(const std::filesystem::path& path, const ReadOptions& options,
                                bool xyz);
Topography read_netcdf_topography(const std::filesystem::path& path, const ReadOptions& options);
Topography read_x3p_topography(const std::filesystem::path& path, const ReadOptions& options);
Topography read_sdf_topography(const std::filesystem::path& path, const ReadOptions& options);

}  // namespace coatfft::topography
