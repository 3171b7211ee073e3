#include "io/grid_file.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/npy.hpp"

namespace coatfft::io {

Field read_grid_file(const std::filesystem::path& file, const Grid& grid, std::string_view key,
                     std::string_view value_word) {
  const std::string ext = file.extension().string();
  COATFFT_REQUIRE(ext == ".npy" || ext == ".csv", key, " = ", file.string(),
                  ": must end in .npy or .csv");
  Field f = ext == ".npy" ? read_npy(file) : read_csv_matrix(file);
  COATFFT_REQUIRE(f.rows() == grid.nx() && f.cols() == grid.ny(), file.string(), ": shape (",
                  f.cols(), ", ", f.rows(), ") but the grid needs (ny, nx) = (", grid.ny(), ", ",
                  grid.nx(), ")");
  for (Eigen::Index j = 0; j < f.cols(); ++j)
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      COATFFT_REQUIRE(std::isfinite(f(i, j)), file.string(), ": row ", j, ", column ", i, ": ",
                      value_word, " ", f(i, j), " is not finite");
  return f;
}

void check_grid_npy(const std::filesystem::path& file, const Grid& grid, std::string_view key,
                    std::string_view what) {
  COATFFT_REQUIRE(file.extension() == ".npy", key, " = ", file.string(),
                  ": a distributed run reads ", what,
                  " from .npy only (numpy.save writes one; `coatfft topography` converts a "
                  "measured surface)");
  // Refused here, before any work, as io/npy_slab.hpp would refuse it after the set-up.
  read_npy_row_header(file, static_cast<std::size_t>(grid.ny()),
                      static_cast<std::size_t>(grid.nx()));
}

}  // namespace coatfft::io
