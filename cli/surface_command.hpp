#pragma once
// `coatfft surface -o FILE.npy --nx N --ny N --lx L --ly L --hurst H (--rms-height R |
// --rms-slope S) [--short-cutoff LS] [--long-cutoff LR] [--seed K]`: a periodic self-affine random
// surface (surfaces/self_affine_surface.hpp) written as a (ny, nx) float64 .npy of heights [m].
#include <cstdint>
#include <filesystem>
#include <optional>

namespace coatfft::cli {

/// The largest cell count a side (a 16384^2 surface takes about 6 GiB while it is made).
inline constexpr long max_surface_cells = 16384;

struct SurfaceOptions {
  std::filesystem::path output;  ///< .npy file
  long nx = 0, ny = 0;           ///< cells, even, in [2, max_surface_cells]
  double lx = 0.0, ly = 0.0;     ///< domain [m]
  double hurst = 0.0;
  std::optional<double> rms_height, rms_slope, short_cutoff, long_cutoff;
  std::uint64_t seed = 0;
};

/// Makes the surface and writes it (through a temporary file renamed when complete); prints one
/// line with its size, rms height and rms slope. InvalidArgument for bad options.
void surface_command(const SurfaceOptions& options);

}  // namespace coatfft::cli
