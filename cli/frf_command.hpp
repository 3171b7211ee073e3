#pragma once
// `coatfft frf SCENE.toml [-o TABLE.csv]`: the FRF of a scene's body as a table, for looking at
// (scripts/plot_frf.py draws it).
#include <filesystem>
#include <optional>

namespace coatfft::cli {

struct FrfOptions {
  std::filesystem::path scene;
  std::filesystem::path output;  ///< CSV file; empty: standard output
  std::optional<double> k_min;   ///< [rad/m]; default 1e-3 / h_total, or 1e2 for a half-space
  std::optional<double> k_max;   ///< [rad/m]; default 1e3 / h_total, or 1e8 for a half-space
  long points = 61;              ///< log-spaced wavenumbers
};

/// Writes the CSV `k,kh_total,frf,frf_over_substrate` (rad/m, -, m/Pa, -).
void frf_command(const FrfOptions& options);

}  // namespace coatfft::cli
