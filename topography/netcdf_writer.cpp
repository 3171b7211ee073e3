#include "topography/netcdf_writer.hpp"

#include <netcdf.h>

#include <map>

#include "core/error.hpp"
#include "scene/npy.hpp"
#include "topography/netcdf_file.hpp"

namespace coatfft::topography {

namespace {
void put_attributes(const NetcdfFile& nc, int var, const NetcdfAttributes& attributes) {
  for (const auto& [name, text] : attributes.text)
    check_netcdf(nc_put_att_text(nc.id(), var, name.c_str(), text.size(), text.c_str()), nc.path(),
                 name);
  for (const auto& [name, value] : attributes.numbers)
    check_netcdf(nc_put_att_double(nc.id(), var, name.c_str(), NC_DOUBLE, 1, &value), nc.path(),
                 name);
}

// A dimension with its coordinate variable (when it has coordinates); returns the dimension id.
int define_dimension(const NetcdfFile& nc, const NetcdfDimension& dimension) {
  int dim = -1;
  check_netcdf(nc_def_dim(nc.id(), dimension.name.c_str(), dimension.size, &dim), nc.path(),
               dimension.name);
  if (!dimension.coordinates.empty()) {
    int var = -1;
    check_netcdf(nc_def_var(nc.id(), dimension.name.c_str(), NC_DOUBLE, 1, &dim, &var), nc.path(),
                 dimension.name);
    put_attributes(nc, var, dimension.attributes);
  }
  return dim;
}

// x or y: the cell centres of the grid [m] and SurfaceTopography's attributes.
NetcdfDimension axis(const Grid& grid, bool x, bool periodic) {
  const std::ptrdiff_t n = x ? grid.nx() : grid.ny();
  NetcdfDimension axis{x ? "x" : "y", static_cast<std::size_t>(n), {}, {}};
  for (std::ptrdiff_t k = 0; k < n; ++k) axis.coordinates.push_back(x ? grid.x(k) : grid.y(k));
  axis.attributes.text = {{"length_unit", "m"}, {"units", "m"}};
  axis.attributes.numbers = {{"length", x ? grid.lx() : grid.ly()}, {"periodic", periodic ? 1 : 0}};
  return axis;
}

// Writes a map variable slice by slice, each (ny, nx) slice transposed to (x, y).
void put_maps(const NetcdfFile& nc, int var, const NetcdfVariable& v, std::size_t leading_dims,
              const Grid& grid) {
  const auto nx = static_cast<std::size_t>(grid.nx()), ny = static_cast<std::size_t>(grid.ny());
  const std::size_t slices = v.data.size() / (nx * ny);
  std::vector<std::size_t> shape(leading_dims + 2), start(leading_dims + 2, 0),
      count(leading_dims + 2, 1);
  std::vector<int> dims(leading_dims + 2);
  check_netcdf(nc_inq_vardimid(nc.id(), var, dims.data()), nc.path(), v.name);
  for (std::size_t d = 0; d < shape.size(); ++d) nc_inq_dimlen(nc.id(), dims[d], &shape[d]);
  count[leading_dims] = nx;
  count[leading_dims + 1] = ny;
  std::vector<double> slice(nx * ny);
  for (std::size_t s = 0; s < slices; ++s) {
    for (std::size_t rest = s, d = leading_dims; d-- > 0; rest /= shape[d])
      start[d] = rest % shape[d];
    const double* from = v.data.data() + s * nx * ny;
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) slice[i * ny + j] = from[j * nx + i];
    check_netcdf(nc_put_vara_double(nc.id(), var, start.data(), count.data(), slice.data()),
                 nc.path(), v.name);
  }
}
}  // namespace

void write_netcdf(const std::filesystem::path& path, const NetcdfDataset& dataset) {
  NetcdfFile nc = NetcdfFile::create(path);
  std::map<std::string, int> dims;
  std::vector<NetcdfDimension> all = {axis(dataset.grid, true, dataset.periodic),
                                      axis(dataset.grid, false, dataset.periodic)};
  all.insert(all.end(), dataset.dimensions.begin(), dataset.dimensions.end());
  for (const auto& dimension : all) dims[dimension.name] = define_dimension(nc, dimension);
  std::vector<int> vars;
  for (const auto& v : dataset.variables) {
    std::vector<int> ids;
    for (const auto& name : v.leading) ids.push_back(dims.at(name));
    if (v.maps) ids.insert(ids.end(), {dims.at("x"), dims.at("y")});
    int var = -1;
    check_netcdf(nc_def_var(nc.id(), v.name.c_str(), NC_DOUBLE, static_cast<int>(ids.size()),
                            ids.data(), &var),
                 nc.path(), v.name);
    put_attributes(nc, var, v.attributes);
    vars.push_back(var);
  }
  put_attributes(nc, NC_GLOBAL, dataset.attributes);
  check_netcdf(nc_enddef(nc.id()), nc.path(), "header");
  for (const auto& dimension : all)
    if (!dimension.coordinates.empty()) {
      int var = -1;
      nc_inq_varid(nc.id(), dimension.name.c_str(), &var);
      check_netcdf(nc_put_var_double(nc.id(), var, dimension.coordinates.data()), nc.path(),
                   dimension.name);
    }
  for (std::size_t k = 0; k < vars.size(); ++k) {
    const auto& v = dataset.variables[k];
    if (v.maps)
      put_maps(nc, vars[k], v, v.leading.size(), dataset.grid);
    else
      check_netcdf(nc_put_var_double(nc.id(), vars[k], v.data.data()), nc.path(), v.name);
  }
  nc.close();
}

}  // namespace coatfft::topography

namespace coatfft::topography {

HeightsFormat heights_format(const std::filesystem::path& target) {
  const std::string ext = target.extension().string();
  if (ext == ".npy") return HeightsFormat::npy;
  COATFFT_REQUIRE(ext == ".nc", target.string(),
                  ": heights are written as .npy or .nc (NetCDF) files (name it *.npy or *.nc)");
  return HeightsFormat::netcdf;
}

void write_heights(const std::filesystem::path& path, HeightsFormat format, const Field& heights,
                   const Grid& grid, bool periodic, const NetcdfAttributes& attributes) {
  COATFFT_REQUIRE(heights.rows() == grid.nx() && heights.cols() == grid.ny(),
                  "write_heights: the heights are not of the grid's shape");
  if (format == HeightsFormat::npy) return scene::write_npy(path, heights);
  NetcdfDataset dataset{grid, periodic, {}, {}, attributes};
  NetcdfVariable z{"heights", {}, {heights.data(), static_cast<std::size_t>(heights.size())}, {}};
  z.attributes.text = {{"units", "m"}, {"long_name", "surface height"}};
  dataset.variables.push_back(z);
  write_netcdf(path, dataset);
}

}  // namespace coatfft::topography
