#pragma once
// `coatfft run SCENE.toml -o OUTDIR`: one displacement computation from a scene file.
#include <filesystem>

namespace coatfft::cli {

struct RunOptions {
  std::filesystem::path scene;
  std::filesystem::path outdir;
  int repeat = 1;  ///< applications timed; apply_seconds is their median
};

/// Runs the scene and writes OUTDIR/{uz.npy, pressure.npy, displacement.csv, summary.json}.
/// Throws InvalidArgument on bad input before anything is written.
void run_command(const RunOptions& options);

}  // namespace coatfft::cli
