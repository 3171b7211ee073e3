#include "io/npy.hpp"
#include "topography/formats.hpp"

namespace coatfft::topography {

// A .npy file carries heights only: no unit, no size, no periodicity.
Topography read_npy_topography(const std::filesystem::path& path, const ReadOptions& options) {
  Topography topography;
  topography.heights = io::read_npy(path, options.max_bytes);
  topography.format = "npy";
  return topography;
}

}  // namespace coatfft::topography
