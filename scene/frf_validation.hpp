#pragma once
// The checks of `coatfft validate-frf` as a library call, for any Frf: a table read from a scene's
// [frf], or an FRF a user supplies from Python. Does `frf` describe the body `claim`? Compared
// are the limits c0 and c_inf against 2/E*_substrate and 2/E*_top; H at sample wavenumbers and
// between them against coatfft's own FRF of the stack (Boussinesq's 2/(E* k) for a half-space);
// the frf-split displacement of `frf` under a Hertz and a uniform-disk load against that of the
// stack (Love's DC-FFT for a half-space); and the continuous Hankel displacement of `frf` against
// the stack's. The sample wavenumbers are a table's own points (where its interpolant is exact,
// and between them where it is furthest from its data); an FRF without points is sampled
// log-spaced over the wavenumbers the grid resolves.
#include <optional>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/axisymmetric_load.hpp"
#include "loads/sampling.hpp"

namespace coatfft::scene {

/// One check: one line of validate-frf's report.
struct FrfCheck {
  /// "c0", "c_inf", "frf_at_points", "frf_between_points", then for each load ("hertz",
  /// "uniform_disk") "<load>_frf_split" and "<load>_hankel".
  std::string name;
  /// Largest relative difference from the reference; NaN when `frf` gave a value that is not
  /// finite.
  double difference = 0.0;
  /// The tolerance applied: the caller's, raised to the floor of what the reference resolves
  /// (1e-10 for the frf-split displacements, 1e-9 for the Hankel integrals).
  double tolerance = 0.0;
  bool passed = false;  ///< difference <= tolerance (false for NaN)
  /// Where the largest difference lies: "k = 1e+05 rad/m", "x = 0, y = 1e-05 m", "r = 0 m"; for
  /// the limits "k -> 0" or "k -> inf", with " (given)" or " (estimated)" for a table.
  std::string detail;
  std::string reference;  ///< what `frf` was compared with, e.g. "2/E*_substrate = 4.9e-12 1/Pa"
};

struct FrfValidation {
  std::vector<FrfCheck> checks;  ///< in the order of FrfCheck::name
  bool passed = false;           ///< every check passed
  /// The FRF of `claim`: "Boussinesq's 2/(E* k) of [substrate]" for a half-space, else
  /// "coatfft's <name> FRF of the stack".
  std::string reference;
};

/// An axisymmetric load of the displacement checks.
struct FrfCheckLoad {
  AxisymmetricLoad kind = AxisymmetricLoad::hertz;
  double amplitude = 1e6;  ///< p0 or p [Pa]
  double radius = 0.0;     ///< a [m], > 0
  Sampling sampling = Sampling::cell_average;
};

struct FrfValidationOptions {
  /// Replaces the load of its kind. Without it both loads are 1 MPa on a radius of a third of the
  /// grid's shorter side, centred, sampled as cell averages (exact cell forces).
  std::optional<FrfCheckLoad> load;
  int threads = 1;  ///< of the two operators' setup and apply(), in 1..max_threads
};

/// Throws InvalidArgument unless tolerance is in (0, 1): validate_frf's own check, for callers
/// that refuse a bad tolerance before they read their input.
void check_validation_tolerance(double tolerance);

/// Checks `frf` against the body `claim` on `grid` (the checks of validate-frf, above), each to
/// the largest relative difference `tolerance`, in (0, 1). Returns every check, failed or not;
/// throws InvalidArgument for a bad tolerance or options, and what `frf` throws.
FrfValidation validate_frf(const Frf& frf, const LayerStack& claim, const Grid& grid,
                           double tolerance, const FrfValidationOptions& options = {});

}  // namespace coatfft::scene
