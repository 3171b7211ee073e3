#include "core/memory.hpp"

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

}  // namespace coatfft
