#pragma once
// Writing topography files in tests: a folder of its own under the system's temporary folder
// (removed with its content), little-endian bytes of values, and the metadata a reader found.
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>

#include "topography/topography.hpp"

namespace coatfft::testing {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("coatfft-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path operator/(const std::string& name) const { return dir_ / name; }
  /// Writes `content` as the file `name` in the folder; returns its path.
  std::filesystem::path write(const std::string& content, const std::string& name = "map") const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return dir_ / name;
  }

 private:
  std::filesystem::path dir_;
};

// Little-endian bytes of a value, assembled from its bits (independent of the host's order).
template <typename T>
void append(std::string& out, T value) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t,
                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint16_t>>;
  const auto bits = std::bit_cast<Bits>(value);
  for (std::size_t k = 0; k < sizeof(T); ++k) out.push_back(static_cast<char>(bits >> (8 * k)));
}

// The value of the metadata entry `name`, or "(absent)".
inline std::string metadata_value(const topography::Topography& topography,
                                  const std::string& name) {
  for (const auto& [key, value] : topography.metadata)
    if (key == name) return value;
  return "(absent)";
}

}  // namespace coatfft::testing
