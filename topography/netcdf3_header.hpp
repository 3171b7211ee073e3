#pragma once
// A NetCDF-3 header's counts checked against the bytes that hold them, before netcdf-c reads it.
// netcdf-c allocates what a header declares (an array for every variable it counts, the values
// of every attribute) before it reads them: 120 bytes that declare 3.8e9 variables ask it for
// 30 GB. Each count here must fit in the bytes left in the file, every element taking at least
// its fixed fields (netCDF's "File Format Specification", CDF-1, CDF-2 and CDF-5).
#include <filesystem>
#include <string_view>

namespace coatfft::topography {

/// Refuses `bytes` (the file `path`) when it starts as a NetCDF-3 file ("CDF" and version 1, 2
/// or 5) whose header declares more dimensions, attributes, variables, names' characters or
/// attribute values than the bytes after the count can hold. A header that ends early is left
/// to netcdf-c, which refuses it; anything else (NetCDF-4) is not looked at.
void require_netcdf3_header_fits(const std::filesystem::path& path, std::string_view bytes);

}  // namespace coatfft::topography
