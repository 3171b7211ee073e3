#pragma once
// The variable `heights` of a NetCDF topography (netcdf_topography.cpp), read into a Field with
// its work and memory bounded by what the file holds, its missing points made NaN.
//
// Missing points are heights equal to `missing_value` (one or several numbers) or `_FillValue`;
// without `_FillValue`, the default fill of the variable's type (NC_FILL_DOUBLE = 9.97e36, ...)
// unless the variable was written without filling (NC_NOFILL), as netCDF4-python reads it: points
// a writer never reached hold that fill. Byte heights are the exception, as there: their default
// fill (-127, 255) is a height like any other. CF's packing (`scale_factor`, `add_offset`) is
// applied to the others.
//
// Bound: the declared heights must fit in the file. NetCDF-3 files (classic, 64-bit offset,
// CDF-5) store them as they are, so they take their declared bytes, and a file shorter than that
// is cut short. A NetCDF-4 (HDF5) file stores only the chunks a writer wrote, and returns the
// fill for the others without storing anything, so 8 KiB can declare 23000 x 23000 heights. Its
// heights therefore also take their declared bytes, or, compressed, at least 1/1032 of them:
// deflate's largest ratio (its longest match, 258 bytes, costs at least 2 bits; RFC 1951,
// Deutsch 1996). No real measurement comes near that ratio; a constant map compressed beyond it
// by another filter (zstd, bzip2, blosc, scale-offset) is refused, with a message saying so.
// The map is then allocated once and read into in blocks: no second copy.
#include <cstdint>

#include "core/types.hpp"
#include "io/netcdf_file.hpp"
#include "topography/topography.hpp"

namespace coatfft::topography {

/// The heights (nx, ny) of variable `var` of `nc`, a file of `file_bytes` bytes, laid out
/// heights(x, y) (the first index x, as SurfaceTopography writes it) or, when its dimensions are
/// named (y, x) as xarray users write, heights(y, x). Missing points are NaN. Refuses text,
/// other than two dimensions, attributes of the wrong type, and a map that cannot be in the file
/// or would not fit `options`' limits, each before the map is allocated.
Field read_netcdf_heights(const io::NetcdfFile& nc, int var, std::uintmax_t file_bytes,
                          const ReadOptions& options);

}  // namespace coatfft::topography
