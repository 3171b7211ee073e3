#include "scene/frf_validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
#include <numbers>
#include <sstream>
#include <utility>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "frf/tabulated_frf.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft::scene {

namespace {

// Floors of the tolerance where the reference, not the FRF checked, limits what can be resolved.
// A frf-split kernel truncates each of its series at SplitKernelOptions::tolerance = 1e-11 of C:
// two kernels of the same FRF agree to that (measured: 3e-13 of max |u| for the tabulated TiN
// example at 320 points per decade, whose interpolation error is 2e-11), so 1e-10 leaves a
// margin of 10. Two Hankel integrals, each to rel_tol = 1e-10, may differ by 2e-10 of u(0):
// 1e-9. A tolerance below these is raised to them, and FrfCheck::tolerance says so.
constexpr double displacement_floor = 1e-10;
constexpr double hankel_rel_tol = 1e-10;
constexpr double hankel_floor = 1e-9;

// Sampling density of an FRF without points of its own: 20 per decade resolve the structure of
// a layered FRF, which changes over about a decade of k h around k h = 1.
constexpr double samples_per_decade = 20.0;

// What `frf` claims to be: the stack, and its exact FRF.
struct Claim {
  const LayerStack& stack;
  std::unique_ptr<Frf> frf;
  std::string name;  // for the report: Boussinesq's, or coatfft's FRF of the stack
};

FrfCheck make_check(std::string name, double difference, double tolerance, std::string detail,
                    std::string reference) {
  const bool passed = difference <= tolerance;  // false for NaN
  return {std::move(name), difference, tolerance, passed, std::move(detail), std::move(reference)};
}

// A coordinate in a report line: 6 significant digits are enough to find the place.
std::string short_number(double value) {
  std::ostringstream os;
  os << std::setprecision(6) << value;
  return os.str();
}

// Log-spaced wavenumbers over what the grid resolves and a decade beyond at each end, for an FRF
// without points: from a tenth of the wavenumber of the grid's longest side to ten times the
// Nyquist wavenumber of its finest cell, where the split kernel still samples H.
std::vector<double> grid_wavenumbers(const Grid& grid) {
  const double k_min = 2.0 * std::numbers::pi / (10.0 * std::max(grid.lx(), grid.ly()));
  const double k_max = 10.0 * std::numbers::pi / std::min(grid.dx(), grid.dy());
  const double decades = std::log10(k_max / k_min);  // >= log10(50): k_max / k_min >= 50 L / d
  const auto n = static_cast<int>(std::ceil(samples_per_decade * decades));
  std::vector<double> ks;
  for (int i = 0; i <= n; ++i) ks.push_back(k_min * std::pow(10.0, decades * i / n));
  return ks;
}

// Three points inside each interval (1/4, 1/2 and 3/4 of the way in ln k): for a table, where an
// interpolant is furthest from its data.
std::vector<double> between_points(const std::vector<double>& k) {
  std::vector<double> points;
  for (std::size_t i = 0; i + 1 < k.size(); ++i)
    for (const double f : {0.25, 0.5, 0.75})
      points.push_back(std::exp((1 - f) * std::log(k[i]) + f * std::log(k[i + 1])));
  return points;
}

// One batch per FRF: an FRF with a large fixed cost per call (a Python callable) pays it once.
FrfCheck frf_check(std::string name, const Frf& frf, const Claim& claim,
                   const std::vector<double>& ks, double tolerance) {
  std::vector<double> h(ks.size()), reference(ks.size());
  frf.evaluate(ks, h);
  claim.frf->evaluate(ks, reference);
  double worst = 0.0;
  double at = ks.front();
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const double d = std::abs(h[i] - reference[i]) / reference[i];
    if (!(d <= worst)) {  // a NaN is kept
      worst = d;
      at = ks[i];
      if (std::isnan(d)) break;
    }
  }
  return make_check(std::move(name), worst, tolerance,
                    detail::concat("k = ", short_number(at), " rad/m"), claim.name);
}

// `note` tells a table's given limit from its estimate; empty for an FRF that states its own.
FrfCheck limit_check(const char* name, double value, const char* note, double reference,
                     const char* where, const char* what, double tolerance) {
  return make_check(name, std::abs(value - reference) / reference, tolerance,
                    detail::concat(where, note), detail::concat(what, " = ", reference, " 1/Pa"));
}

const char* limit_note(const TabulatedFrf* table, bool (TabulatedFrf::*estimated)() const) {
  if (table == nullptr) return "";
  return (table->*estimated)() ? " (estimated)" : " (given)";
}

// The limits, and H at the sample wavenumbers and between them.
std::vector<FrfCheck> frf_checks(const Frf& frf, const Claim& claim, const Grid& grid,
                                 double tolerance) {
  const auto* table = dynamic_cast<const TabulatedFrf*>(&frf);
  const std::vector<double> ks = table != nullptr ? table->k() : grid_wavenumbers(grid);
  const LayerStack& stack = claim.stack;
  const Material& top =
      stack.is_homogeneous() ? stack.substrate() : stack.coatings().front().material;
  return {limit_check("c0", frf.c0(), limit_note(table, &TabulatedFrf::c0_estimated),
                      claim.frf->c0(), "k -> 0", "2/E*_substrate", tolerance),
          limit_check("c_inf", frf.c_inf(), limit_note(table, &TabulatedFrf::c_inf_estimated),
                      2.0 / top.plane_strain_modulus(), "k -> inf", "2/E*_top", tolerance),
          frf_check("frf_at_points", frf, claim, ks, tolerance),
          frf_check("frf_between_points", frf, claim, between_points(ks), tolerance)};
}

// The two loads of the displacement checks: `replacement` for its kind, else centred on a third
// of the shorter side (cell averages, exact cell forces).
std::array<FrfCheckLoad, 2> check_loads(const Grid& grid,
                                        const std::optional<FrfCheckLoad>& replacement) {
  const double a = std::min(grid.lx(), grid.ly()) / 3.0;
  std::array<FrfCheckLoad, 2> loads{
      FrfCheckLoad{AxisymmetricLoad::hertz, 1e6, a, Sampling::cell_average},
      FrfCheckLoad{AxisymmetricLoad::uniform_disk, 1e6, a, Sampling::cell_average}};
  if (replacement) {
    const FrfCheckLoad& load = *replacement;
    COATFFT_REQUIRE(std::isfinite(load.amplitude) && load.amplitude != 0,
                    "validate_frf: load amplitude = ", load.amplitude,
                    " Pa, but it must be finite and not 0");
    COATFFT_REQUIRE(std::isfinite(load.radius) && load.radius > 0,
                    "validate_frf: load radius = ", load.radius,
                    " m, but it must be finite and > 0");
    loads[load.kind == AxisymmetricLoad::hertz ? 0 : 1] = load;
  }
  return loads;
}

const char* load_name(const FrfCheckLoad& load) {
  return load.kind == AxisymmetricLoad::hertz ? "hertz" : "uniform_disk";
}

Field load_field(const Grid& grid, const FrfCheckLoad& load) {
  return load.kind == AxisymmetricLoad::hertz
             ? hertz_pressure(grid, load.amplitude, load.radius, load.sampling)
             : uniform_disk_pressure(grid, load.amplitude, load.radius, load.sampling);
}

// max |u - reference| / max |reference| over the grid, and where.
FrfCheck field_check(std::string name, const Grid& grid, const Field& u, const Field& reference,
                     double tolerance, std::string reference_name) {
  Eigen::Index i = 0, j = 0;
  const double worst = (u - reference).abs().maxCoeff(&i, &j);
  const double scale = reference.abs().maxCoeff();
  return make_check(
      std::move(name), u.allFinite() ? worst / scale : NAN, std::max(tolerance, displacement_floor),
      detail::concat("x = ", short_number(grid.x(i)), ", y = ", short_number(grid.y(j)), " m"),
      std::move(reference_name));
}

// u(r) of `frf` against the stack's, both continuous (Hankel integrals), at r = 0, a/2, a, 2a,
// relative to |u(0)| of the stack.
FrfCheck hankel_check(const FrfCheckLoad& load, const Frf& frf, const Claim& claim,
                      double tolerance) {
  const double a = load.radius;
  const auto u = [&](const Frf& h, double r) {
    return hankel_displacement(h, load.kind, load.amplitude, a, r, hankel_rel_tol);
  };
  const double scale = std::abs(u(*claim.frf, 0.0));
  double worst = 0.0, at = 0.0;
  std::string failure;
  for (const double r : {0.0, 0.5 * a, a, 2.0 * a}) {
    double d = NAN;
    try {
      d = std::abs(u(frf, r) - u(*claim.frf, r)) / scale;
    } catch (const InvalidArgument&) {
      throw;
    } catch (const Error& e) {
      // The integral of an FRF whose k H does not reach the c_inf it states does not converge:
      // that is a failed check of the FRF, not a failure of the validation.
      failure = detail::concat(" (the integral of the FRF failed: ", e.what(), ")");
    }
    if (!(d <= worst)) {
      worst = d;
      at = r;
    }
    if (!failure.empty()) break;
  }
  return make_check(
      detail::concat(load_name(load), "_hankel"), worst, std::max(tolerance, hankel_floor),
      detail::concat("r = ", short_number(at), " m", failure),
      detail::concat("Hankel integral of ", claim.name, ", rel_tol ", hankel_rel_tol));
}

// The frf-split displacements of `frf` against the stack's (Love's DC-FFT for a half-space,
// whose coefficients frf-split reproduces exactly for a homogeneous FRF), and the Hankel ones.
std::vector<FrfCheck> displacement_checks(const Frf& frf, const Claim& claim, const Grid& grid,
                                          double tolerance, const FrfValidationOptions& options) {
  const std::array<FrfCheckLoad, 2> loads = check_loads(grid, options.load);
  // The split kernel at its default tolerance, which the floors above assume.
  OperatorOptions split;
  split.method = Method::frf_split;
  split.threads = options.threads;
  OperatorOptions reference_options = split;
  const bool love = claim.stack.is_homogeneous();
  if (love) reference_options.method = Method::dcfft;
  BuiltOperator frf_op = make_operator(grid, frf, split);
  BuiltOperator reference_op = make_operator(grid, claim.stack, reference_options);
  const std::string reference_name =
      love ? "Love's DC-FFT of [substrate]" : "frf-split of " + claim.name;
  std::vector<FrfCheck> checks;
  for (const FrfCheckLoad& load : loads) {
    const Field p = load_field(grid, load);
    checks.push_back(field_check(detail::concat(load_name(load), "_frf_split"), grid,
                                 frf_op.op->apply(p), reference_op.op->apply(p), tolerance,
                                 reference_name));
    checks.push_back(hankel_check(load, frf, claim, tolerance));
  }
  return checks;
}

}  // namespace

void check_validation_tolerance(double tolerance) {
  COATFFT_REQUIRE(tolerance > 0 && tolerance < 1, "--tolerance = ", tolerance,
                  " must be in (0, 1)");
}

FrfValidation validate_frf(const Frf& frf, const LayerStack& claim, const Grid& grid,
                           double tolerance, const FrfValidationOptions& options) {
  check_validation_tolerance(tolerance);
  std::unique_ptr<Frf> exact = make_frf(claim);
  std::string name = claim.is_homogeneous() ? "Boussinesq's 2/(E* k) of [substrate]"
                                            : "coatfft's " + exact->name() + " FRF of the stack";
  const Claim reference{claim, std::move(exact), name};
  FrfValidation result{frf_checks(frf, reference, grid, tolerance), true, std::move(name)};
  for (FrfCheck& check : displacement_checks(frf, reference, grid, tolerance, options))
    result.checks.push_back(std::move(check));
  result.passed = std::all_of(result.checks.begin(), result.checks.end(),
                              [](const FrfCheck& check) { return check.passed; });
  return result;
}

}  // namespace coatfft::scene
