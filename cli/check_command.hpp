#pragma once
// `coatfft check SCENE.toml`: validates a scene exactly as `coatfft run` does before it computes
// (scene, input files, load, memory, the FRF pipelines' predicted error) and prints what a run
// would compute, as JSON on stdout, without building an operator or writing anything.
#include <filesystem>
#include <optional>

namespace coatfft::cli {

struct CheckOptions {
  std::filesystem::path scene;
  std::optional<double> max_memory;  ///< as `coatfft run --max-memory`
};

/// Prints {scene, problem, method, nx, ny, lx, ly, dx, dy, estimated_memory_bytes,
/// memory_drivers, available_memory_bytes, predicted_error (frf-spectral, frf-dcfft), warnings}.
/// Throws InvalidArgument for anything `coatfft run` would refuse before computing.
void check_command(const CheckOptions& options);

}  // namespace coatfft::cli
