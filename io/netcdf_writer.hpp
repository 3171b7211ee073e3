#pragma once
// Writing fields as one NetCDF file in the layout SurfaceTopography reads and xarray opens
// (docs/measured_surfaces.md, "NetCDF layout"): dimensions x and y with coordinate variables of
// the cell centres [m] carrying `length`, `periodic`, `length_unit` and CF's `units`; each map a
// variable over (..., x, y), x the first of the two as SurfaceTopography writes `heights`; other
// dimensions (depths, loads, stress components) with their own coordinates before them.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft::io {

/// Text and numeric attributes of a variable or of the file, in their order.
struct NetcdfAttributes {
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
};

/// A dimension other than x and y, with its coordinate values (empty: none, as for a stress
/// component index) and their attributes.
struct NetcdfDimension {
  std::string name;
  std::size_t size = 0;
  std::vector<double> coordinates;
  NetcdfAttributes attributes;
};

/// A variable whose last two dimensions are x and y: `data` in coatfft's memory order (C order
/// over `leading` dims, then y, then x fastest: a Field, or fields stacked as the .npy files
/// are), written as (leading..., x, y). Or, with `maps` false, a variable over `leading` only.
struct NetcdfVariable {
  std::string name;
  std::vector<std::string> leading;  ///< names of dimensions declared in NetcdfDataset
  std::span<const double> data;
  NetcdfAttributes attributes;
  bool maps = true;
};

struct NetcdfDataset {
  Grid grid;
  bool periodic = false;
  std::vector<NetcdfDimension> dimensions;
  std::vector<NetcdfVariable> variables;
  NetcdfAttributes attributes;  ///< of the file (global)
  /// The grid's rows that the maps' data hold: all of them (rows < 0), or a rank's slab in a
  /// collective write (io/netcdf_collective.hpp), `rows` rows from `first_row` on.
  std::ptrdiff_t first_row = 0;
  std::ptrdiff_t rows = -1;
  /// Whether this writer puts the coordinates and the variables without maps (in a collective
  /// write, the first rank only; the others take part in those calls with nothing to put).
  bool puts_shared = true;
  /// The values of a map transposed to the file's (x, y) at once, a block of x at a time: the
  /// writer's memory beyond the maps (32 MiB by default).
  std::size_t buffer_values = std::size_t{1} << 22;
};

/// Writes `dataset` as a new NetCDF-3 file `path` (64-bit offsets, or the 64-bit data format
/// where needs_64bit_data), refusing an existing one.
void write_netcdf(const std::filesystem::path& path, const NetcdfDataset& dataset);

/// Whether `dataset` needs NetCDF-3's 64-bit data format (CDF-5: netcdf-c 4.4 and later, PnetCDF,
/// netCDF4-python and xarray read it): the 64-bit offset format holds a variable of at most
/// 2^32 - 4 bytes but for the last one (NetCDF's format specification), which two maps of
/// 23171^2 cells, or the stress planes of a few thousand cells a side, exceed. Files that fit keep
/// the 64-bit offset format, which SurfaceTopography's own reader takes.
bool needs_64bit_data(const NetcdfDataset& dataset);

class NetcdfFile;

/// The two halves of write_netcdf, which a collective write separates to ask for collective
/// access in between: `dataset`'s dimensions, variables and attributes defined in the new file
/// `nc` (define mode ended); then its values put.
void define_netcdf(NetcdfFile& nc, const NetcdfDataset& dataset);
void put_netcdf(NetcdfFile& nc, const NetcdfDataset& dataset);

}  // namespace coatfft::io

namespace coatfft::io {

enum class HeightsFormat { npy, netcdf };

/// The format of a heights file named `target`: .npy or .nc (NetCDF); InvalidArgument otherwise.
HeightsFormat heights_format(const std::filesystem::path& target);

/// The dataset of a height map [m] on `grid`: the variable `heights`, as SurfaceTopography names
/// it, of `heights` (the whole map (nx, ny), or a slab's rows (nx, rows) with first_row and rows
/// set), with `attributes` as the file's.
NetcdfDataset heights_dataset(const Grid& grid, bool periodic, const Field& heights,
                              const NetcdfAttributes& attributes);

/// Writes a height map [m] on `grid` as `path`: a (ny, nx) float64 .npy file, or a NetCDF file
/// holding the variable `heights` as SurfaceTopography names it, with `attributes` as the file's.
void write_heights(const std::filesystem::path& path, HeightsFormat format, const Field& heights,
                   const Grid& grid, bool periodic, const NetcdfAttributes& attributes = {});

}  // namespace coatfft::io
