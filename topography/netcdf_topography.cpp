// NetCDF topographies in SurfaceTopography's layout: a variable `heights` over two dimensions x
// and y (heights(x, y): the first index is x, as SurfaceTopography writes it; a file whose
// dimensions are named (y, x), as xarray users often write, is read accordingly), and optional
// coordinate variables x and y whose attributes give the physical size (`length`), the unit
// (`length_unit`, or `unit`/`units`) and the periodicity (`periodic`, non-zero for periodic).
// The heights themselves, their missing points and their bound: netcdf_heights.hpp. Attributes
// of the wrong type are refused (netcdf_attributes.hpp).
#include <netcdf.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/input_file.hpp"
#include "io/netcdf_file.hpp"
#include "topography/formats.hpp"
#include "topography/netcdf3_header.hpp"
#include "topography/netcdf_attributes.hpp"
#include "topography/netcdf_heights.hpp"
#include "topography/units.hpp"

namespace coatfft::topography {

namespace {
std::optional<std::string> unit_attribute(const io::NetcdfFile& nc, int var, const char* owner) {
  for (const char* name : {"length_unit", "unit", "units"})
    if (auto unit = text_attribute(nc, var, owner, name)) return unit;
  return {};
}

// What a coordinate variable (x or y) says: its length [its unit] and unit, and periodicity.
struct Coordinate {
  std::optional<double> length;
  std::optional<std::string> unit;
  std::optional<bool> periodic;
};

Coordinate read_coordinate(const io::NetcdfFile& nc, const char* name) {
  int var = -1;
  if (nc_inq_varid(nc.id(), name, &var) != NC_NOERR) return {};
  Coordinate axis{number_attribute(nc, var, name, "length"), unit_attribute(nc, var, name), {}};
  if (const auto periodic = number_attribute(nc, var, name, "periodic"))
    axis.periodic = *periodic != 0;
  COATFFT_REQUIRE(!axis.length || (std::isfinite(*axis.length) && *axis.length > 0),
                  nc.path().string(), ": the attribute length of ", name,
                  " must be a positive number, not ", *axis.length);
  return axis;
}

// The file's global text attributes (instrument, history, ...), as metadata.
std::vector<std::pair<std::string, std::string>> global_text(const io::NetcdfFile& nc) {
  int count = 0;
  std::vector<std::pair<std::string, std::string>> metadata;
  if (nc_inq_natts(nc.id(), &count) != NC_NOERR) return metadata;
  for (int k = 0; k < count; ++k) {
    char name[NC_MAX_NAME + 1] = {};
    if (nc_inq_attname(nc.id(), NC_GLOBAL, k, name) != NC_NOERR) continue;
    nc_type type = NC_NAT;
    std::size_t length = 0;
    if (nc_inq_att(nc.id(), NC_GLOBAL, name, &type, &length) != NC_NOERR ||
        (type != NC_CHAR && (type != NC_STRING || length != 1)))
      continue;  // numbers and lists are no metadata text
    if (auto text = text_attribute(nc, NC_GLOBAL, "the file", name))
      metadata.emplace_back(name, *text);
  }
  return metadata;
}

}  // namespace

Topography read_netcdf_topography(const std::filesystem::path& path, const ReadOptions& options) {
  std::string bytes = io::read_input_file(path, "a NetCDF file", options.max_bytes);
  require_netcdf3_header_fits(path, bytes);
  const io::NetcdfFile nc = io::NetcdfFile::open_memory(path, bytes);
  int var = -1;
  COATFFT_REQUIRE(nc_inq_varid(nc.id(), "heights", &var) == NC_NOERR, path.string(),
                  ": no variable named heights (the layout of docs/measured_surfaces.md)");
  // Every attribute is checked before the heights are read.
  const Coordinate x = read_coordinate(nc, "x"), y = read_coordinate(nc, "y");
  Topography topography;
  topography.unit =
      unit_attribute(nc, var, "heights").value_or(x.unit.value_or(y.unit.value_or("")));
  topography.heights = read_netcdf_heights(nc, var, bytes.size(), options);
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
