#include "topography/reader_support.hpp"

#include "core/memory.hpp"

namespace coatfft::topography {

void require_point_limit(const std::filesystem::path& path, std::string_view sizes, std::size_t nx,
                         std::size_t ny, const ReadOptions& options) {
  const std::uintmax_t max_points = options.max_bytes / sizeof(double);
  if (nx > max_points || (nx > 0 && ny > max_points / nx))
    refuse(path, sizes, " = ", nx, " * ", ny, " points, more than the limit of ", max_points,
           " points (", options.max_bytes, " bytes)");
  // The map as read and the one made from it (the heights in metres detrended, or the gap):
  // two doubles a point, asked for before the first is allocated, so that a file declaring more
  // points than the machine holds ends in one line, not in the kernel's OOM killer.
  const double points = static_cast<double>(nx) * static_cast<double>(ny);
  const MemoryNeed need{2.0 * sizeof(double) * points,
                        detail::concat(sizes, " = ", nx, " * ", ny, " points")};
  require_memory(need, options.max_memory, path.string() + ": the map", "--max-memory",
                 "read a smaller map");
}

}  // namespace coatfft::topography
