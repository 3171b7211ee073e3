#pragma once
// `coatfft topography FILE [-o OUT] [--unit U] [--detrend none|mean|plane]
// [--missing refuse|fill] [--lx L --ly L] [--gap] [--max-memory M] [--overwrite]`: reads a measured
// topography (topography/ topography.hpp), prints its summary as JSON
// (topography/topography_summary.hpp) and, with -o, writes its heights [m] as detrended and filled,
// as .npy or NetCDF (.nc).
#include <filesystem>
#include <optional>
#include <string>

namespace coatfft::cli {

struct TopographyOptions {
  std::filesystem::path input;
  std::optional<std::filesystem::path> output;  ///< .npy or .nc
  std::string unit;                             ///< of a file that carries none
  std::string detrend = "none";
  std::string missing = "refuse";
  std::optional<double> lx, ly;  ///< [m], for a file that carries no size (must agree otherwise)
  /// Write the gap max(z) - z of the detrended heights ([contact] indenter = "height_map"), .npy.
  bool gap = false;
  /// The memory reading and filling the map may take [bytes]; what the machine has if not given.
  std::optional<double> max_memory;
  bool overwrite = false;  ///< replace an existing output file (else it is refused)
};

/// Reads, summarises and writes; InvalidArgument for bad options or files, before any output.
void topography_command(const TopographyOptions& options);

}  // namespace coatfft::cli
