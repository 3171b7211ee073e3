#pragma once
// `coatfft validate-frf SCENE.toml [--tolerance 1e-6]`: checks a scene's [frf] table against what
// its [substrate] and [[coating]] say the body is (docs/scene_format.md, "validate-frf"): the
// limits c0 and c_inf against 2/E*_substrate and 2/E*_top; H at the table's points and between
// them against coatfft's own FRF of the stack (Boussinesq's 2/(E* k) for a half-space); the
// frf-split displacement of the table under a Hertz and a uniform-disk load against that of the
// stack (Love's DC-FFT for a half-space); and the table's continuous Hankel displacement against
// the stack's. One report line per check; the command fails when any check exceeds its tolerance.
#include <filesystem>

namespace coatfft::cli {

struct ValidateFrfOptions {
  std::filesystem::path scene;
  double tolerance = 1e-6;  ///< largest relative difference accepted, in (0, 1)
};

/// Prints the report on stdout and returns true when every check is within its tolerance; names
/// the failed checks on stderr and returns false otherwise. Throws InvalidArgument for bad input:
/// a scene `coatfft run` would refuse, one without [frf] (nothing to validate) or without
/// [substrate] (nothing to validate against), a tolerance outside (0, 1).
bool validate_frf_command(const ValidateFrfOptions& options);

}  // namespace coatfft::cli
