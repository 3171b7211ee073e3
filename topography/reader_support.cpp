#include "topography/reader_support.hpp"

#include "core/memory.hpp"

namespace coatfft::topography {

void require_file_point_limit(const std::filesystem::path& path, std::string_view sizes,
                              std::size_t nx, std::size_t ny, const ReadOptions& options) {
  const std::uintmax_t max_points = options.max_bytes / sizeof(double);
  if (nx > max_points || (nx > 0 && ny > max_points / nx))
    refuse(path, sizes, " = ", nx, " * ", ny, " points, more than the limit of ", max_points,
           " points (", options.max_bytes, " bytes)");
}

void require_map_memory(const std::filesystem::path& path, std::string_view sizes, std::size_t nx,
                        std::size_t ny, const ReadOptions& options) {
  // The map the reader allocates, a double a point, asked for before it is allocated, so that a
  // file declaring more points than the machine holds ends in one line, not in the kernel's OOM
  // killer. The readers hold the map once (docs/measured_surfaces.md).
  const double points = static_cast<double>(nx) * static_cast<double>(ny);
  const MemoryNeed need{sizeof(double) * points,
                        detail::concat(sizes, " = ", nx, " * ", ny, " points")};
  require_memory(need, options.max_memory, path.string() + ": the map", "--max-memory",
                 "read a smaller map");
}

void require_point_limit(const std::filesystem::path& path, std::string_view sizes, std::size_t nx,
                         std::size_t ny, const ReadOptions& options) {
  require_file_point_limit(path, sizes, nx, ny, options);
  require_map_memory(path, sizes, nx, ny, options);
}

}  // namespace coatfft::topography
