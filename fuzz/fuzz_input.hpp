#pragma once
// Support of the libFuzzer targets: the readers under test take a path, so each input is written
// to a file in a folder of the fuzzing process's own, removed when the process ends normally.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace coatfft::fuzz {

class ScratchFolder {
 public:
  /// Creates TMPDIR/coatfft_NAME_XXXXXX (mkdtemp: a new folder, whatever runs beside).
  explicit ScratchFolder(const std::string& name) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / ("coatfft_" + name + "_XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();
    folder_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& folder() const { return folder_; }

  /// Writes `size` bytes to the file `name` of the folder (replacing it) and returns its path.
  std::filesystem::path write(const std::string& name, const std::uint8_t* data,
                              std::size_t size) const {
    const std::filesystem::path path = folder_ / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) std::abort();  // a full disk is no finding of the reader's
    return path;
  }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    return write(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }

 private:
  std::filesystem::path folder_;
};

}  // namespace coatfft::fuzz
