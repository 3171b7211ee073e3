#include "topography/netcdf_heights.hpp"

#include <netcdf.h>
#include <netcdf_filter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "topography/netcdf_attributes.hpp"
#include "topography/reader_support.hpp"

namespace coatfft::topography {

namespace {
using Index = Eigen::Index;

// Deflate's largest compression ratio (RFC 1951: a 258-byte match in no fewer than 2 bits).
constexpr std::uintmax_t kDeflateMaxRatio = 1032;
// Values read at a time (2 MiB of doubles): the buffer of a transposed read.
constexpr std::size_t kBlockValues = std::size_t{1} << 18;

// The heights' numeric type and its size in the file [bytes]; text and user-defined types
// (compound, enum, vlen, opaque) are refused.
std::size_t value_size(const io::NetcdfFile& nc, int var, nc_type& type) {
  io::check_netcdf(nc_inq_vartype(nc.id(), var, &type), nc.path(), "heights");
  char name[NC_MAX_NAME + 1] = {};
  std::size_t size = 0;
  io::check_netcdf(nc_inq_type(nc.id(), type, name, &size), nc.path(), "heights");
  COATFFT_REQUIRE(type != NC_CHAR && type != NC_STRING, nc.path().string(),
                  ": the variable heights holds text (of type ", name, "), not numbers");
  COATFFT_REQUIRE(type <= NC_MAX_ATOMIC_TYPE, nc.path().string(),
                  ": the variable heights is of the user-defined type ", name, ", not numbers");
  return size;
}

// The heights' sizes (first, second dimension) and whether they are named (y, x).
bool y_first(const io::NetcdfFile& nc, int var, std::array<std::size_t, 2>& sizes) {
  int dims = 0;
  io::check_netcdf(nc_inq_varndims(nc.id(), var, &dims), nc.path(), "heights");
  COATFFT_REQUIRE(dims == 2, nc.path().string(), ": the variable heights has ", dims,
                  " dimensions, not 2 (x and y)");
  std::array<int, 2> ids{};
  io::check_netcdf(nc_inq_vardimid(nc.id(), var, ids.data()), nc.path(), "heights");
  std::array<std::string, 2> names;
  for (int d = 0; d < 2; ++d) {
    char name[NC_MAX_NAME + 1] = {};
    io::check_netcdf(nc_inq_dim(nc.id(), ids[d], name, &sizes[d]), nc.path(), "heights");
    names[d] = name;
  }
  return names[0] == "y" && names[1] == "x";
}

// Refuses heights that cannot be in a file of `file_bytes` (netcdf_heights.hpp, "Bound"); after
// require_file_point_limit, so that nx ny times the value size fits in 64 bits.
void require_in_file(const io::NetcdfFile& nc, int var, std::size_t size, std::size_t nx,
                     std::size_t ny, std::uintmax_t file_bytes) {
  std::size_t filters = 0;
  if (nc_inq_var_filter_ids(nc.id(), var, &filters, nullptr) != NC_NOERR) filters = 0;
  const std::uintmax_t declared = std::uintmax_t{nx} * ny * size;
  const std::uintmax_t least =
      filters > 0 ? (declared + kDeflateMaxRatio - 1) / kDeflateMaxRatio : declared;
  if (least <= file_bytes) return;
  if (filters == 0)
    refuse(nc.path(), "heights: x * y = ", nx, " * ", ny, " points of ", size, " bytes take ",
           declared, " bytes, more than the file's ", file_bytes,
           ": the file is cut short, or its heights were never written");
  refuse(nc.path(), "heights: x * y = ", nx, " * ", ny, " points of ", size,
         " bytes, compressed, take at least ", least, " bytes (deflate compresses at most ",
         kDeflateMaxRatio, ":1), more than the file's ", file_bytes,
         ": its heights were never written, or compressed beyond deflate (write them with zlib "
         "or uncompressed)");
}

// Default fills, as netcdf.h defines them, by type; none for bytes (netcdf_heights.hpp).
std::optional<double> default_fill(nc_type type) {
  switch (type) {
    case NC_SHORT:
      return NC_FILL_SHORT;
    case NC_USHORT:
      return NC_FILL_USHORT;
    case NC_INT:
      return NC_FILL_INT;
    case NC_UINT:
      return NC_FILL_UINT;
    case NC_INT64:
      return static_cast<double>(NC_FILL_INT64);
    case NC_UINT64:
      return static_cast<double>(NC_FILL_UINT64);
    case NC_FLOAT:
      return NC_FILL_FLOAT;
    case NC_DOUBLE:
      return NC_FILL_DOUBLE;
    default:
      return {};
  }
}

// A stored height to metres of the file's unit: missing values to NaN, CF's packing applied.
struct Decoding {
  std::vector<double> missing;
  double scale = 1.0, offset = 0.0;

  double operator()(double stored) const {
    if (std::find(missing.begin(), missing.end(), stored) != missing.end()) return std::nan("");
    return stored * scale + offset;
  }
};

Decoding decoding(const io::NetcdfFile& nc, int var, nc_type type) {
  Decoding d{number_attributes(nc, var, "heights", "missing_value"), 1.0, 0.0};
  if (const auto fill = number_attribute(nc, var, "heights", "_FillValue")) {
    d.missing.push_back(*fill);
  } else {
    int no_fill = 0;
    io::check_netcdf(nc_inq_var_fill(nc.id(), var, &no_fill, nullptr), nc.path(), "heights");
    if (const auto type_fill = default_fill(type); type_fill && !no_fill)
      d.missing.push_back(*type_fill);
  }
  const auto packing = [&](const char* name, double absent) {
    const auto value = number_attribute(nc, var, "heights", name);
    COATFFT_REQUIRE(!value || std::isfinite(*value), nc.path().string(), ": the attribute ", name,
                    " of heights must be finite, not ", *value);
    return value.value_or(absent);
  };
  d.scale = packing("scale_factor", 1.0);
  d.offset = packing("add_offset", 0.0);
  return d;
}

// Reads the heights into `z` by blocks of rows of the variable (its first dimension): straight
// into z's storage for (y, x), whose rows are z's columns; through a buffer for (x, y).
void read_blocks(const io::NetcdfFile& nc, int var, const Decoding& decode, bool yx, Field& z) {
  const auto rows = static_cast<std::size_t>(yx ? z.cols() : z.rows());
  const auto row = static_cast<std::size_t>(yx ? z.rows() : z.cols());
  const std::size_t block = std::max<std::size_t>(1, kBlockValues / row);
  std::vector<double> buffer(yx ? 0 : std::min(rows, block) * row);
  for (std::size_t first = 0; first < rows; first += block) {
    const std::array<std::size_t, 2> start{first, 0}, count{std::min(block, rows - first), row};
    double* values = yx ? z.data() + first * row : buffer.data();
    io::check_netcdf(nc_get_vara_double(nc.id(), var, start.data(), count.data(), values),
                     nc.path(), "reading heights");
    std::transform(values, values + count[0] * row, values, decode);
    if (yx) continue;
    // z's columns are written in order; the block's rows are read a value at a time, each
    // cache line of them used for the next few columns.
    for (std::size_t j = 0; j < row; ++j)
      for (std::size_t a = 0; a < count[0]; ++a)
        z(static_cast<Index>(first + a), static_cast<Index>(j)) = buffer[a * row + j];
  }
}
}  // namespace

Field read_netcdf_heights(const io::NetcdfFile& nc, int var, std::uintmax_t file_bytes,
                          const ReadOptions& options) {
  nc_type type = NC_NAT;
  const std::size_t size = value_size(nc, var, type);
  std::array<std::size_t, 2> sizes{};
  const bool yx = y_first(nc, var, sizes);
  const std::size_t nx = yx ? sizes[1] : sizes[0], ny = yx ? sizes[0] : sizes[1];
  COATFFT_REQUIRE(nx > 0 && ny > 0, nc.path().string(), ": heights of ", nx, " x ", ny,
                  " points are empty");
  // Checked without forming nx ny, which may overflow for the dimensions a file can declare.
  require_file_point_limit(nc.path(), "heights: x * y", nx, ny, options);
  // What the file cannot hold is named as such before the memory it would take.
  require_in_file(nc, var, size, nx, ny, file_bytes);
  require_map_memory(nc.path(), "heights: x * y", nx, ny, options);
  const Decoding decode = decoding(nc, var, type);
  Field z(static_cast<Index>(nx), static_cast<Index>(ny));
  read_blocks(nc, var, decode, yx, z);
  return z;
}

}  // namespace coatfft::topography
