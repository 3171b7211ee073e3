#pragma once
// `coatfft surface -o FILE.npy|FILE.nc --nx N --ny N --lx L --ly L --hurst H (--rms-height R |
// --rms-slope S) [--short-cutoff LS] [--long-cutoff LR] [--seed K] [--overwrite]`: a periodic
// self-affine random surface (surfaces/self_affine_surface.hpp) written as a (ny, nx) float64 .npy
// of heights [m], or as a NetCDF file in SurfaceTopography's layout (io/netcdf_writer.hpp).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "surfaces/self_affine_surface.hpp"  // max_surface_cells
#ifdef COATFFT_WITH_MPI
#include "distributed/communicator.hpp"
#endif

namespace coatfft::cli {

struct SurfaceOptions {
  std::filesystem::path output;  ///< .npy or .nc file
  long nx = 0, ny = 0;           ///< cells, even, in [2, max_surface_cells]
  double lx = 0.0, ly = 0.0;     ///< domain [m]
  double hurst = 0.0;
  std::optional<double> rms_height, rms_slope, short_cutoff, long_cutoff;
  /// --seed as typed: parsed by parse_seed (CLI11 would saturate -1 or 2^64 to 2^64 - 1).
  std::string seed = "0";
  bool overwrite = false;  ///< replace an existing output file (else it is refused)
};

/// The --seed text as an integer in [0, 2^64 - 1]: decimal digits only, or InvalidArgument
/// naming `option` (a sign, an exponent, a fraction or a value out of range are refused, not
/// rounded or saturated into another surface's seed).
std::uint64_t parse_seed(std::string_view text, std::string_view option);

/// Makes the surface and writes it (through a temporary file renamed when complete); prints one
/// line with its size, rms height and rms slope. InvalidArgument for bad options.
void surface_command(const SurfaceOptions& options);

#ifdef COATFFT_WITH_MPI
/// The same by the ranks of `comm` (docs/scale.md): each makes its rows (self_affine_slab) and
/// writes them into the one .npy file (MPI-IO); the same file as the serial command's, byte for
/// byte. NetCDF output is refused. Rank 0 stages and commits the file and prints the line.
void surface_command(const SurfaceOptions& options, const Communicator& comm);
#endif

}  // namespace coatfft::cli
