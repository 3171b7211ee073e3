#include "topography/topography.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "topography/formats.hpp"
#include "topography/reader_support.hpp"
#include "topography/units.hpp"

namespace coatfft::topography {

namespace fs = std::filesystem;

MissingPoints missing_points_from_name(std::string_view name, std::string_view what) {
  if (name == "refuse") return MissingPoints::refuse;
  if (name == "fill") return MissingPoints::fill;
  throw InvalidArgument(
      detail::concat(what, " must be \"refuse\" or \"fill\", not ", io::quoted_excerpt(name)));
}

namespace {
Topography read_format(const fs::path& path, const ReadOptions& options) {
  const std::string ext = lower_ascii(path.extension().string());
  if (ext == ".npy") return read_npy_topography(path, options);
  if (ext == ".csv" || ext == ".txt" || ext == ".asc" || ext == ".xyz")
    return read_text_topography(path, options, ext == ".xyz");
  if (ext == ".nc") return read_netcdf_topography(path, options);
  if (ext == ".x3p") return read_x3p_topography(path, options);
  if (ext == ".sdf") return read_sdf_topography(path, options);
  throw InvalidArgument(detail::concat(path.string(), ": unknown topography format ",
                                       io::quoted_excerpt(ext),
                                       " (known: .npy, .csv, .txt, .asc, .xyz, .nc, .x3p, .sdf)"));
}

// Metres per unit of the file: its own unit, or the caller's for a file without one (metres if
// neither); a caller's unit that disagrees with the file's is refused.
double file_scale(const fs::path& path, Topography& topography, const std::string& unit) {
  const std::string where = path.string() + ": the unit";
  if (topography.unit.empty()) {
    topography.unit = unit;
    return unit.empty() ? 1.0 : metres_per_unit(unit, "the unit asked for");
  }
  const double scale = metres_per_unit(topography.unit, where);
  // Both units are known ones here (metres_per_unit passed), so they are printed as they are.
  COATFFT_REQUIRE(unit.empty() || metres_per_unit(unit, "the unit asked for") == scale,
                  path.string(), ": the file's unit is \"", topography.unit, "\", not the unit \"",
                  unit, "\" asked for");
  return scale;
}

// Counts the NaN points, refuses infinite ones, and fills or refuses the NaN ones.
void check_heights(const fs::path& path, Topography& topography, const ReadOptions& options) {
  Field& z = topography.heights;
  COATFFT_REQUIRE(z.rows() >= 2 && z.cols() >= 2, path.string(), ": ", z.rows(), " x ", z.cols(),
                  " points: a topography needs at least 2 x 2");
  std::size_t nan = 0;
  for (Eigen::Index j = 0; j < z.cols(); ++j)
    for (Eigen::Index i = 0; i < z.rows(); ++i) {
      COATFFT_REQUIRE(!std::isinf(z(i, j)), path.string(), ": row ", j, ", column ", i,
                      ": an infinite height");
      nan += std::isnan(z(i, j));
    }
  topography.missing = nan;
  if (nan == 0) return;
  COATFFT_REQUIRE(options.missing == MissingPoints::fill, path.string(), ": ", nan, " of ",
                  z.size(), " points are missing (NaN or marked invalid); they can be filled (",
                  options.fill_hint, ": docs/measured_surfaces.md)");
  fill_missing_points(z, options.max_memory, path.string());
}
}  // namespace

Topography read_topography(const fs::path& path, const ReadOptions& options) {
  Topography topography = read_format(path, options);
  const double scale = file_scale(path, topography, options.unit);
  topography.heights *= scale;
  if (topography.lx) *topography.lx *= scale;
  if (topography.ly) *topography.ly *= scale;
  COATFFT_REQUIRE(topography.lx.has_value() == topography.ly.has_value(), path.string(),
                  ": the file gives the size along one axis only");
  check_heights(path, topography, options);
  return topography;
}

}  // namespace coatfft::topography
