#include "io/netcdf_writer.hpp"

#include <netcdf.h>

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "io/netcdf_file.hpp"
#include "io/npy.hpp"

namespace coatfft::io {

namespace {
void put_attributes(NetcdfFile& nc, int var, const NetcdfAttributes& attributes) {
  for (const auto& [name, text] : attributes.text)
    nc.check(nc_put_att_text(nc.id(), var, name.c_str(), text.size(), text.c_str()), name);
  for (const auto& [name, value] : attributes.numbers)
    nc.check(nc_put_att_double(nc.id(), var, name.c_str(), NC_DOUBLE, 1, &value), name);
}

// A dimension with its coordinate variable (when it has coordinates); returns the dimension id.
int define_dimension(NetcdfFile& nc, const NetcdfDimension& dimension) {
  int dim = -1;
  nc.check(nc_def_dim(nc.id(), dimension.name.c_str(), dimension.size, &dim), dimension.name);
  if (!dimension.coordinates.empty()) {
    int var = -1;
    nc.check(nc_def_var(nc.id(), dimension.name.c_str(), NC_DOUBLE, 1, &dim, &var), dimension.name);
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

// Every dimension of the file: x, y, then the dataset's own.
std::vector<NetcdfDimension> all_dimensions(const NetcdfDataset& dataset) {
  std::vector<NetcdfDimension> all = {axis(dataset.grid, true, dataset.periodic),
                                      axis(dataset.grid, false, dataset.periodic)};
  all.insert(all.end(), dataset.dimensions.begin(), dataset.dimensions.end());
  return all;
}

int variable_id(NetcdfFile& nc, const std::string& name) {
  int var = -1;
  nc.check(nc_inq_varid(nc.id(), name.c_str(), &var), name);
  return var;
}

// The sizes of a variable's dimensions, as the file declares them.
std::vector<std::size_t> variable_shape(NetcdfFile& nc, int var, const std::string& name) {
  int n = 0;
  nc.check(nc_inq_varndims(nc.id(), var, &n), name);
  std::vector<int> dims(static_cast<std::size_t>(n));
  std::vector<std::size_t> shape(dims.size());
  nc.check(nc_inq_vardimid(nc.id(), var, dims.data()), name);
  for (std::size_t d = 0; d < dims.size(); ++d)
    nc.check(nc_inq_dimlen(nc.id(), dims[d], &shape[d]), name);
  return shape;
}

// A variable's values whole, or, when `puts` is false, nothing (count 0), still as a call.
void put_whole(NetcdfFile& nc, const std::string& name, const double* values, bool puts) {
  const int var = variable_id(nc, name);
  std::vector<std::size_t> count = variable_shape(nc, var, name);
  const std::vector<std::size_t> start(count.size(), 0);
  if (!puts) count.assign(count.size(), 0);
  nc.check(nc_put_vara_double(nc.id(), var, start.data(), count.data(), values), name);
}

// to[i * rows + j] = from[j * stride + i] for i < width: `width` columns of a slice's rows (rows,
// stride) as the file's (x, y) block (width, rows), by tiles that stay in cache.
void transpose_columns(const double* from, std::size_t stride, std::size_t width, std::size_t rows,
                       double* to) {
  constexpr std::size_t tile = 32;
  for (std::size_t j0 = 0; j0 < rows; j0 += tile)
    for (std::size_t i0 = 0; i0 < width; i0 += tile)
      for (std::size_t j = j0; j < std::min(j0 + tile, rows); ++j)
        for (std::size_t i = i0; i < std::min(i0 + tile, width); ++i)
          to[i * rows + j] = from[j * stride + i];
}

// Writes a map variable slice by slice (the product of its leading dimensions), each slice's rows
// (rows, nx) transposed to the file's (x, y) a block of columns at a time: a buffer of at most
// d.buffer_values values, not a copy of the map. The number of calls depends on the file's shape
// alone, the same on every rank of a collective write.
void put_maps(NetcdfFile& nc, const NetcdfVariable& v, const NetcdfDataset& d) {
  const int var = variable_id(nc, v.name);
  const std::vector<std::size_t> shape = variable_shape(nc, var, v.name);
  COATFFT_REQUIRE(shape.size() >= 2, "write_netcdf: ", v.name, " is not a map in the file");
  const std::size_t leading = shape.size() - 2, nx = shape[leading], ny = shape[leading + 1];
  std::size_t slices = 1;
  for (std::size_t k = 0; k < leading; ++k) slices *= shape[k];
  const auto rows = static_cast<std::size_t>(d.rows < 0 ? d.grid.ny() : d.rows);
  COATFFT_REQUIRE(v.data.size() == slices * nx * rows, "write_netcdf: ", v.name,
                  " does not hold the rows of its dimensions");
  const std::size_t columns = std::clamp<std::size_t>(d.buffer_values / ny, 1, nx);
  std::vector<double> block(columns * rows);
  std::vector<std::size_t> start(shape.size(), 0), count(shape.size(), 1);
  start[leading + 1] = rows > 0 ? static_cast<std::size_t>(d.first_row) : 0;
  count[leading + 1] = rows;
  for (std::size_t s = 0; s < slices; ++s) {
    for (std::size_t rest = s, k = leading; k-- > 0; rest /= shape[k]) start[k] = rest % shape[k];
    for (std::size_t i0 = 0; i0 < nx; i0 += columns) {
      start[leading] = i0;
      count[leading] = std::min(columns, nx - i0);
      transpose_columns(v.data.data() + s * nx * rows + i0, nx, count[leading], rows, block.data());
      nc.check(nc_put_vara_double(nc.id(), var, start.data(), count.data(), block.data()), v.name);
    }
  }
}
}  // namespace

void define_netcdf(NetcdfFile& nc, const NetcdfDataset& dataset) {
  // Every value is put: filling the variables first would write the file twice.
  int fill = 0;
  nc.check(nc_set_fill(nc.id(), NC_NOFILL, &fill), "fill mode");
  std::map<std::string, int> dims;
  for (const auto& dimension : all_dimensions(dataset))
    dims[dimension.name] = define_dimension(nc, dimension);
  for (const auto& v : dataset.variables) {
    std::vector<int> ids;
    for (const auto& name : v.leading) ids.push_back(dims.at(name));
    if (v.maps) ids.insert(ids.end(), {dims.at("x"), dims.at("y")});
    int var = -1;
    nc.check(nc_def_var(nc.id(), v.name.c_str(), NC_DOUBLE, static_cast<int>(ids.size()),
                        ids.data(), &var),
             v.name);
    put_attributes(nc, var, v.attributes);
  }
  put_attributes(nc, NC_GLOBAL, dataset.attributes);
  nc.check(nc_enddef(nc.id()), "header");
}

void put_netcdf(NetcdfFile& nc, const NetcdfDataset& dataset) {
  for (const auto& dimension : all_dimensions(dataset))
    if (!dimension.coordinates.empty())
      put_whole(nc, dimension.name, dimension.coordinates.data(), dataset.puts_shared);
  for (const auto& v : dataset.variables) {
    if (v.maps)
      put_maps(nc, v, dataset);
    else
      put_whole(nc, v.name, v.data.data(), dataset.puts_shared);
  }
}

bool needs_64bit_data(const NetcdfDataset& dataset) {
  std::map<std::string, double> sizes;
  for (const auto& dimension : all_dimensions(dataset))
    sizes[dimension.name] = static_cast<double>(dimension.size);
  constexpr double limit = 4294967292.0;  // 2^32 - 4 bytes
  // The variables are defined after the coordinates: the dataset's last is the file's last.
  for (std::size_t k = 0; k + 1 < dataset.variables.size(); ++k) {
    const NetcdfVariable& v = dataset.variables[k];
    double bytes = sizeof(double) * (v.maps ? sizes.at("x") * sizes.at("y") : 1.0);
    for (const auto& name : v.leading) bytes *= sizes.at(name);
    if (bytes > limit) return true;
  }
  return false;
}

void write_netcdf(const std::filesystem::path& path, const NetcdfDataset& dataset) {
  NetcdfFile nc = NetcdfFile::create(path, needs_64bit_data(dataset));
  define_netcdf(nc, dataset);
  put_netcdf(nc, dataset);
  nc.close();
}

}  // namespace coatfft::io

namespace coatfft::io {

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
  if (format == HeightsFormat::npy) return io::write_npy(path, heights);
  write_netcdf(path, heights_dataset(grid, periodic, heights, attributes));
}

NetcdfDataset heights_dataset(const Grid& grid, bool periodic, const Field& heights,
                              const NetcdfAttributes& attributes) {
  NetcdfDataset dataset{grid, periodic, {}, {}, attributes};
  NetcdfVariable z{"heights", {}, {heights.data(), static_cast<std::size_t>(heights.size())}, {}};
  z.attributes.text = {{"units", "m"}, {"long_name", "surface height"}};
  dataset.variables.push_back(z);
  return dataset;
}

}  // namespace coatfft::io
