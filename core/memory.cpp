#include "core/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.hpp"

namespace coatfft {

namespace {

std::string gigabytes(double bytes) {
  return detail::concat(std::round(bytes / 1e7) / 100, " GB");
}

}  // namespace

std::optional<double> available_memory() {
  std::optional<double> bytes;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0;
    std::string unit;
    meminfo >> kib >> unit;
    if (key == "MemAvailable:") bytes = kib * 1024.0;
  }
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  double limit = 0;
  if (cgroup >> limit && (!bytes || limit < *bytes)) bytes = limit;  // "max" fails to parse
  // An address-space limit (ulimit -v, RLIMIT_AS) leaves what the process has not mapped yet.
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    std::ifstream statm("/proc/self/statm");
    double pages = 0;
    statm >> pages;
    const double room = std::max(
        0.0, static_cast<double>(as.rlim_cur) - pages * static_cast<double>(::getpagesize()));
    if (!bytes || room < *bytes) bytes = room;
  }
  return bytes;
}

void require_memory(const MemoryNeed& need, std::optional<double> limit, std::string_view who,
                    std::string_view limit_name, std::string_view remedy) {
  const std::optional<double> have = limit ? limit : available_memory();
  if (!have) return;
  const std::string how =
      limit ? detail::concat("is the limit (", limit_name, ")")
            : (limit_name.empty() ? std::string("is available")
                                  : detail::concat("is available (", limit_name, " to change)"));
  COATFFT_REQUIRE(need.bytes <= *have, who, " needs about ", gigabytes(need.bytes),
                  " of memory, driven by ", need.drivers, ", but ", gigabytes(*have), " ", how,
                  ": ", remedy);
}

void require_grid_memory(std::ptrdiff_t nx, std::ptrdiff_t ny, double fields,
                         std::string_view who) {
  const double cells = static_cast<double>(nx) * static_cast<double>(ny);
  require_memory({fields * 8.0 * cells, detail::concat("grid ", nx, " x ", ny)}, std::nullopt, who,
                 "", "use fewer cells");
}

}  // namespace coatfft
