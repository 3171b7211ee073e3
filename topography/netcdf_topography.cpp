// NetCDF topographies in SurfaceTopography's layout: a variable `heights` over two dimensions x
// and y (heights(x, y): the first index is x, as SurfaceTopography writes it; a file whose
// dimensions are named (y, x), as xarray users often write, is read accordingly), and optional
// coordinate variables x and y whose attributes give the physical size (`length`), the unit
// (`length_unit`, or `unit`/`units`) and the periodicity (`periodic`, non-zero for periodic).
// Missing points are heights equal to the variable's `_FillValue` or `missing_value`, or NaN;
// CF's packing (`scale_factor`, `add_offset`) is applied.
#include <netcdf.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/input_file.hpp"
#include "topography/formats.hpp"
#include "topography/netcdf_file.hpp"
#include "topography/reader_support.hpp"
#include "topography/units.hpp"

namespace coatfft::topography {

namespace {
using Index = Eigen::Index;

// A text attribute: NC_CHAR, or a single NC_STRING (what netCDF4-python writes in NETCDF4 files
// for text beyond ASCII, such as "µm").
std::optional<std::string> text_attribute(int file, int var, const char* name) {
  nc_type type{};
  std::size_t length = 0;
  if (nc_inq_att(file, var, name, &type, &length) != NC_NOERR) return {};
  if (type == NC_STRING && length == 1) {
    char* text = nullptr;
    if (nc_get_att_string(file, var, name, &text) != NC_NOERR) return {};
    std::string out = text ? text : "";
    nc_free_string(1, &text);
    return out;
  }
  if (type != NC_CHAR) return {};
  std::string text(length, '\0');
  if (nc_get_att_text(file, var, name, text.data()) != NC_NOERR) return {};
  while (!text.empty() && text.back() == '\0') text.pop_back();
  return text;
}

std::optional<double> number_attribute(int file, int var, const char* name) {
  nc_type type{};
  std::size_t length = 0;
  if (nc_inq_att(file, var, name, &type, &length) != NC_NOERR || length != 1 || type == NC_CHAR ||
      type == NC_STRING)
    return {};
  double value = 0;
  if (nc_get_att_double(file, var, name, &value) != NC_NOERR) return {};
  return value;
}

std::optional<std::string> unit_attribute(int file, int var) {
  for (const char* name : {"length_unit", "unit", "units"})
    if (auto unit = text_attribute(file, var, name)) return unit;
  return {};
}

// What a coordinate variable (x or y) says: its length [its unit] and unit, and periodicity.
struct Coordinate {
  std::optional<double> length;
  std::optional<std::string> unit;
  std::optional<bool> periodic;
};

Coordinate read_coordinate(const NetcdfFile& nc, const char* name) {
  int var = -1;
  if (nc_inq_varid(nc.id(), name, &var) != NC_NOERR) return {};
  Coordinate axis{number_attribute(nc.id(), var, "length"), unit_attribute(nc.id(), var), {}};
  if (const auto periodic = number_attribute(nc.id(), var, "periodic"))
    axis.periodic = *periodic != 0;
  COATFFT_REQUIRE(!axis.length || (std::isfinite(*axis.length) && *axis.length > 0),
                  nc.path().string(), ": the attribute length of ", name,
                  " must be a positive number, not ", *axis.length);
  return axis;
}

// The heights' two dimensions: true when they are named (y, x), the Field's own layout.
bool y_first(const NetcdfFile& nc, int var, std::array<std::size_t, 2>& sizes) {
  int dims = 0;
  check_netcdf(nc_inq_varndims(nc.id(), var, &dims), nc.path(), "heights");
  COATFFT_REQUIRE(dims == 2, nc.path().string(), ": the variable heights has ", dims,
                  " dimensions, not 2 (x and y)");
  std::array<int, 2> ids{};
  check_netcdf(nc_inq_vardimid(nc.id(), var, ids.data()), nc.path(), "heights");
  std::array<std::string, 2> names;
  for (int d = 0; d < 2; ++d) {
    char name[NC_MAX_NAME + 1] = {};
    check_netcdf(nc_inq_dim(nc.id(), ids[d], name, &sizes[d]), nc.path(), "heights");
    names[d] = name;
  }
  return names[0] == "y" && names[1] == "x";
}

// The file's global text attributes (instrument, history, ...), as metadata.
std::vector<std::pair<std::string, std::string>> global_text(const NetcdfFile& nc) {
  int count = 0;
  std::vector<std::pair<std::string, std::string>> metadata;
  if (nc_inq_natts(nc.id(), &count) != NC_NOERR) return metadata;
  for (int k = 0; k < count; ++k) {
    char name[NC_MAX_NAME + 1] = {};
    if (nc_inq_attname(nc.id(), NC_GLOBAL, k, name) != NC_NOERR) continue;
    if (auto text = text_attribute(nc.id(), NC_GLOBAL, name)) metadata.emplace_back(name, *text);
  }
  return metadata;
}

// The heights as stored, CF packing applied and fill values made NaN.
std::vector<double> read_values(const NetcdfFile& nc, int var, std::size_t count) {
  std::vector<double> values(count);
  check_netcdf(nc_get_var_double(nc.id(), var, values.data()), nc.path(), "reading heights");
  const auto fill = number_attribute(nc.id(), var, "_FillValue");
  const auto missing = number_attribute(nc.id(), var, "missing_value");
  const double scale = number_attribute(nc.id(), var, "scale_factor").value_or(1.0);
  const double offset = number_attribute(nc.id(), var, "add_offset").value_or(0.0);
  for (double& v : values) {
    if ((fill && v == *fill) || (missing && v == *missing))
      v = std::nan("");
    else
      v = v * scale + offset;
  }
  return values;
}
}  // namespace

Topography read_netcdf_topography(const std::filesystem::path& path, const ReadOptions& options) {
  std::string bytes = scene::read_input_file(path, "a NetCDF file", options.max_bytes);
  const NetcdfFile nc = NetcdfFile::open_memory(path, bytes);
  int var = -1;
  COATFFT_REQUIRE(nc_inq_varid(nc.id(), "heights", &var) == NC_NOERR, path.string(),
                  ": no variable named heights (the layout of docs/measured_surfaces.md)");
  std::array<std::size_t, 2> sizes{};
  const bool yx = y_first(nc, var, sizes);
  const std::size_t nx = yx ? sizes[1] : sizes[0], ny = yx ? sizes[0] : sizes[1];
  COATFFT_REQUIRE(nx > 0 && ny > 0, path.string(), ": heights of ", nx, " x ", ny,
                  " points are empty");
  // Checked without forming nx ny, which may overflow for the dimensions a file can declare.
  require_point_limit(path, "heights: x * y", nx, ny, options);
  const std::vector<double> values = read_values(nc, var, nx * ny);
  Topography topography;
  topography.heights.resize(static_cast<Index>(nx), static_cast<Index>(ny));
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      topography.heights(static_cast<Index>(i), static_cast<Index>(j)) =
          yx ? values[j * nx + i] : values[i * ny + j];
  const Coordinate x = read_coordinate(nc, "x"), y = read_coordinate(nc, "y");
  topography.unit = unit_attribute(nc.id(), var).value_or(x.unit.value_or(y.unit.value_or("")));
  // The lengths in the heights' unit, each converted from its own axis's unit.
  const auto in_height_unit = [&](const Coordinate& axis,
                                  const char* name) -> std::optional<double> {
    if (!axis.length) return {};
    if (!axis.unit || topography.unit.empty() || *axis.unit == topography.unit) return axis.length;
    const std::string where = path.string() + ": the unit of " + name;
    return *axis.length * metres_per_unit(*axis.unit, where) /
           metres_per_unit(topography.unit, path.string() + ": the unit of heights");
  };
  topography.lx = in_height_unit(x, "x");
  topography.ly = in_height_unit(y, "y");
  if (x.periodic || y.periodic)
    topography.periodic = x.periodic.value_or(false) && y.periodic.value_or(false);
  topography.metadata = global_text(nc);
  topography.format = "netcdf";
  return topography;
}

}  // namespace coatfft::topography
