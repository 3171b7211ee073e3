#pragma once
// A folder of its own under the system's temporary folder, removed with its content: for tests
// that write the files they read.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace coatfft::testing
