#pragma once
// Writing topography files in tests: a folder of its own under the system's temporary folder
// (removed with its content), little-endian bytes of values, and the metadata a reader found.
#include <malloc.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/error.hpp"
#include "tests/address_sanitized.hpp"
#include "tests/bounded_call.hpp"
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

// Reading options with the file size limit `max_bytes`, or the memory limit `max_memory` [bytes],
// the others their defaults.
inline topography::ReadOptions size_limit(std::uintmax_t max_bytes) {
  topography::ReadOptions options;
  options.max_bytes = max_bytes;
  return options;
}
inline topography::ReadOptions memory_limit(double max_memory) {
  topography::ReadOptions options;
  options.max_memory = max_memory;
  return options;
}

// Blocks of 64 kB and more are mapped anew and given back when freed, in the whole test process
// (glibc otherwise keeps freed blocks of up to 32 MiB for reuse, which a child of run_bounded
// would inherit and use without growing): the child's limit then counts every block.
inline const bool kLargeBlocksMapped = mallopt(M_MMAP_THRESHOLD, 1 << 16) == 1;

// What `call` did in a child process whose address space may grow by `headroom` bytes beyond
// the test's and that is stopped after `seconds` (coatfft_test::run_bounded): a reader that
// allocates what a file declares, rather than what it holds, ends in "out of memory" there (or
// is killed), not in a refusal.
struct BoundedRun {
  std::string outcome;  ///< the InvalidArgument's message, "returned", "out of memory", ...
  double seconds = 0;   ///< wall-clock time of the child
};

inline BoundedRun run_bounded(std::uintmax_t headroom, int seconds,
                              const std::function<void()>& call) {
  const coatfft_test::BoundedCall run = coatfft_test::run_bounded(
      [&] {
        // AddressSanitizer's allocator takes no mallopt (nor the address-space bound).
        if (!kLargeBlocksMapped && !coatfft_test::address_sanitized()) _exit(1);
        try {
          call();
        } catch (const std::bad_alloc&) {
          throw std::runtime_error("out of memory");
        } catch (const InvalidArgument&) {
          throw;
        } catch (const std::exception& error) {
          throw std::runtime_error(std::string("another error: ") + error.what());
        }
      },
      headroom, static_cast<unsigned>(seconds));
  if (!run.returned) return {"killed or stopped", run.seconds};
  return {run.error.empty() ? "returned" : run.error, run.seconds};
}

}  // namespace coatfft::testing
