#include "cli/staged_output.hpp"

#include <unistd.h>

#include "core/error.hpp"

namespace coatfft::cli {

namespace fs = std::filesystem;

StagedOutput::StagedOutput(fs::path outdir) : outdir_(std::move(outdir)) {
  COATFFT_REQUIRE(!outdir_.empty(), "output folder: empty path");
  COATFFT_REQUIRE(!fs::exists(outdir_) || fs::is_directory(outdir_), "output folder ",
                  outdir_.string(), " exists and is not a folder");
  // Staging beside OUTDIR keeps the final renames on one file system.
  const fs::path parent = fs::absolute(outdir_).parent_path();
  staging_ = parent / detail::concat(".", fs::absolute(outdir_).filename().string(), ".partial-",
                                     ::getpid());
  std::error_code ec;
  fs::create_directories(staging_, ec);
  COATFFT_REQUIRE(!ec, "cannot create ", staging_.string(), ": ", ec.message());
}

StagedOutput::~StagedOutput() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

fs::path StagedOutput::path(const std::string& name) {
  names_.push_back(name);
  return staging_ / name;
}

void StagedOutput::commit() {
  std::error_code ec;
  fs::create_directories(outdir_, ec);
  COATFFT_REQUIRE(!ec, "cannot create output folder ", outdir_.string(), ": ", ec.message());
  for (const auto& name : names_) {
    fs::rename(staging_ / name, outdir_ / name, ec);
    COATFFT_REQUIRE(!ec, "cannot move ", name, " into ", outdir_.string(), ": ", ec.message());
  }
}

}  // namespace coatfft::cli
