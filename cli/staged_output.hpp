#pragma once
// All-or-nothing output: files are written into a hidden staging folder beside OUTDIR and moved
// into OUTDIR only when every file is complete, so a failed run leaves no partial output.
#include <filesystem>
#include <string>
#include <vector>

namespace coatfft::cli {

class StagedOutput {
 public:
  explicit StagedOutput(std::filesystem::path outdir);
  ~StagedOutput();  ///< removes the staging folder and whatever is left in it
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Path in the staging folder for the output file `name` (e.g. "uz.npy").
  std::filesystem::path path(const std::string& name);
  /// Moves every staged file into OUTDIR (created if needed); each move is an atomic rename.
  void commit();

 private:
  std::filesystem::path outdir_;
  std::filesystem::path staging_;
  std::vector<std::string> names_;
};

}  // namespace coatfft::cli
