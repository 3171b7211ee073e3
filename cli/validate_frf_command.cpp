#include "cli/validate_frf_command.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/resources.hpp"
#include "cli/scene.hpp"
#include "convolution/make_operator.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/tabulated_frf.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft::cli {

namespace {

// Floors of the tolerance where the reference, not the table, limits what can be resolved. A
// frf-split kernel truncates each of its series at SplitKernelOptions::tolerance = 1e-11 of C:
// two kernels of the same FRF agree to that (measured: 3e-13 of max |u| for the tabulated TiN
// example at 320 points per decade, whose interpolation error is 2e-11), so 1e-10 leaves a
// margin of 10. Two Hankel integrals, each to rel_tol = 1e-10, may differ by 2e-10 of u(0):
// 1e-9. A --tolerance below these is raised to them, and the report says so.
constexpr double displacement_floor = 1e-10;
constexpr double hankel_rel_tol = 1e-10;
constexpr double hankel_floor = 1e-9;

struct CheckLine {
  std::string name;
  double difference = 0.0;  // largest relative difference
  std::string where;
  double tolerance = 0.0;
  std::string reference;
  bool ok() const { return difference <= tolerance; }  // false for NaN
};

// What the table claims to be: the stack of [substrate] and [[coating]], and its exact FRF.
struct Claim {
  const LayerStack& stack;
  std::unique_ptr<Frf> frf;
  std::string name;  // for the report: Boussinesq's, or coatfft's FRF of the stack
};

// A coordinate in a report line: 6 significant digits are enough to find the place.
std::string short_number(double value) {
  std::ostringstream os;
  os << std::setprecision(6) << value;
  return os.str();
}

// Three points inside each interval of the table (1/4, 1/2 and 3/4 of the way in ln k), where an
// interpolant is furthest from its data.
std::vector<double> between_points(const std::vector<double>& k) {
  std::vector<double> points;
  for (std::size_t i = 0; i + 1 < k.size(); ++i)
    for (const double f : {0.25, 0.5, 0.75})
      points.push_back(std::exp((1 - f) * std::log(k[i]) + f * std::log(k[i + 1])));
  return points;
}

CheckLine frf_check(std::string name, const Frf& table, const Claim& claim,
                    const std::vector<double>& ks, double tolerance) {
  double worst = 0.0;
  double at = ks.front();
  for (const double k : ks) {
    const double reference = (*claim.frf)(k);
    const double d = std::abs(table(k) - reference) / reference;
    if (!(d <= worst)) {  // a NaN is kept
      worst = d;
      at = k;
      if (std::isnan(d)) break;
    }
  }
  return {std::move(name), worst, detail::concat("k = ", short_number(at), " rad/m"), tolerance,
          claim.name};
}

CheckLine limit_check(const char* name, double value, bool estimated, double reference,
                      const char* where, const char* what, double tolerance) {
  return {name, std::abs(value - reference) / reference,
          detail::concat(where, estimated ? " (estimated)" : " (given)"), tolerance,
          detail::concat(what, " = ", reference, " 1/Pa")};
}

// The two axisymmetric loads of the displacement checks: the scene's [pressure] when it is one
// of them, else centred on a third of the shorter side (cell averages, exact cell forces).
struct TestLoad {
  AxisymmetricLoad kind;
  const char* name;
  double amplitude, radius;
  Sampling sampling;
};

std::array<TestLoad, 2> test_loads(const Scene& scene) {
  const double a = std::min(scene.grid.lx(), scene.grid.ly()) / 3.0;
  std::array<TestLoad, 2> loads{
      TestLoad{AxisymmetricLoad::hertz, "hertz", 1e6, a, Sampling::cell_average},
      TestLoad{AxisymmetricLoad::uniform_disk, "uniform_disk", 1e6, a, Sampling::cell_average}};
  if (scene.pressure && scene.pressure->kind != PressureKind::file) {
    TestLoad& load = loads[scene.pressure->kind == PressureKind::hertz ? 0 : 1];
    load.amplitude = scene.pressure->amplitude;
    load.radius = scene.pressure->radius;
    load.sampling = scene.pressure->sampling;
  }
  return loads;
}

Field load_field(const Grid& grid, const TestLoad& load) {
  return load.kind == AxisymmetricLoad::hertz
             ? hertz_pressure(grid, load.amplitude, load.radius, load.sampling)
             : uniform_disk_pressure(grid, load.amplitude, load.radius, load.sampling);
}

// max |u - reference| / max |reference| over the grid, and where.
CheckLine field_check(std::string name, const Grid& grid, const Field& u, const Field& reference,
                      double tolerance, std::string reference_name) {
  Eigen::Index i = 0, j = 0;
  const double worst = (u - reference).abs().maxCoeff(&i, &j);
  const double scale = reference.abs().maxCoeff();
  return {std::move(name), u.allFinite() ? worst / scale : NAN,
          detail::concat("x = ", short_number(grid.x(i)), ", y = ", short_number(grid.y(j)), " m"),
          tolerance, std::move(reference_name)};
}

// u(r) of the table against the stack's, both continuous (Hankel integrals), at r = 0, a/2, a,
// 2a, relative to |u(0)| of the stack.
CheckLine hankel_check(const TestLoad& load, const Frf& table, const Claim& claim,
                       double tolerance) {
  const double a = load.radius;
  const auto u = [&](const Frf& frf, double r) {
    return hankel_displacement(frf, load.kind, load.amplitude, a, r, hankel_rel_tol);
  };
  const double scale = std::abs(u(*claim.frf, 0.0));
  double worst = 0.0, at = 0.0;
  for (const double r : {0.0, 0.5 * a, a, 2.0 * a}) {
    const double d = std::abs(u(table, r) - u(*claim.frf, r)) / scale;
    if (!(d <= worst)) {
      worst = d;
      at = r;
    }
  }
  return {detail::concat(load.name, "_hankel"), worst,
          detail::concat("r = ", short_number(at), " m"), std::max(tolerance, hankel_floor),
          detail::concat("Hankel integral of ", claim.name, ", rel_tol ", hankel_rel_tol)};
}

// The frf-split displacements of the table against the stack's (Love's DC-FFT for a half-space,
// whose coefficients frf-split reproduces exactly for a homogeneous FRF).
std::vector<CheckLine> displacement_checks(const Scene& scene, const Claim& claim,
                                           double tolerance) {
  // The split kernel at its default tolerance, which the floors above assume, whatever the
  // scene's method would use.
  OperatorOptions split;
  split.method = Method::frf_split;
  split.threads = scene.method.options.threads;
  OperatorOptions reference_options = split;
  const bool love = claim.stack.is_homogeneous();
  if (love) reference_options.method = Method::dcfft;
  BuiltOperator table_op = make_operator(scene.grid, *scene.frf, split);
  BuiltOperator reference_op = make_operator(scene.grid, claim.stack, reference_options);
  const std::string reference_name =
      love ? "Love's DC-FFT of [substrate]" : "frf-split of " + claim.name;
  std::vector<CheckLine> checks;
  for (const TestLoad& load : test_loads(scene)) {
    const Field p = load_field(scene.grid, load);
    checks.push_back(field_check(detail::concat(load.name, "_frf_split"), scene.grid,
                                 table_op.op->apply(p), reference_op.op->apply(p),
                                 std::max(tolerance, displacement_floor), reference_name));
    checks.push_back(hankel_check(load, *scene.frf, claim, tolerance));
  }
  return checks;
}

std::vector<CheckLine> all_checks(const Scene& scene, const TabulatedFrf& table, const Claim& claim,
                                  double tolerance) {
  const LayerStack& stack = claim.stack;
  const Material& top =
      stack.is_homogeneous() ? stack.substrate() : stack.coatings().front().material;
  std::vector<CheckLine> checks{
      limit_check("c0", table.c0(), table.c0_estimated(), claim.frf->c0(), "k -> 0",
                  "2/E*_substrate", tolerance),
      limit_check("c_inf", table.c_inf(), table.c_inf_estimated(), 2.0 / top.plane_strain_modulus(),
                  "k -> inf", "2/E*_top", tolerance),
      frf_check("frf_at_points", table, claim, table.k(), tolerance),
      frf_check("frf_between_points", table, claim, between_points(table.k()), tolerance)};
  for (CheckLine& check : displacement_checks(scene, claim, tolerance))
    checks.push_back(std::move(check));
  return checks;
}

void print_report(const Scene& scene, const TabulatedFrf& table, const Claim& claim,
                  const std::vector<CheckLine>& checks) {
  std::cout << "validate-frf: [frf] " << scene.frf_file.string() << " (" << table.size()
            << " points, k = " << table.k().front() << " to " << table.k().back()
            << " rad/m) against " << claim.name << "\n";
  std::cout << std::left << std::setw(26) << "check" << std::setw(12) << "max rel diff"
            << std::setw(39) << "  at" << std::setw(11) << "tolerance"
            << "result    reference\n";
  for (const CheckLine& c : checks) {
    std::ostringstream diff, tol;
    diff << std::scientific << std::setprecision(2) << c.difference;
    tol << std::scientific << std::setprecision(1) << c.tolerance;
    std::cout << std::setw(26) << c.name << std::setw(12) << diff.str() << "  " << std::setw(36)
              << c.where << ' ' << std::setw(11) << tol.str() << std::setw(10)
              << (c.ok() ? "ok" : "FAILED") << c.reference << '\n';
  }
}

}  // namespace

bool validate_frf_command(const ValidateFrfOptions& options) {
  COATFFT_REQUIRE(options.tolerance > 0 && options.tolerance < 1,
                  "--tolerance = ", options.tolerance, " must be in (0, 1)");
  const Scene scene = read_scene(options.scene);
  const auto* table = dynamic_cast<const TabulatedFrf*>(scene.frf.get());
  COATFFT_REQUIRE(table != nullptr, options.scene.string(),
                  ": no [frf] section, so no table to validate (validate-frf checks a body given "
                  "as a table against its [substrate] and [[coating]])");
  COATFFT_REQUIRE(scene.body.has_value(), options.scene.string(),
                  ": no [substrate], so nothing to validate the [frf] table against; describe the "
                  "body the table claims to be with [substrate] (and [[coating]])");
  check_memory(scene, std::nullopt);
  std::unique_ptr<Frf> exact = make_frf(*scene.body);
  const std::string name = scene.body->is_homogeneous()
                               ? "Boussinesq's 2/(E* k) of [substrate]"
                               : "coatfft's " + exact->name() + " FRF of the stack";
  const Claim claim{*scene.body, std::move(exact), name};
  const std::vector<CheckLine> checks = all_checks(scene, *table, claim, options.tolerance);
  print_report(scene, *table, claim, checks);
  std::string failed;
  for (const CheckLine& c : checks)
    if (!c.ok()) failed += (failed.empty() ? "" : ", ") + c.name;
  if (failed.empty()) {
    std::cout << "validate-frf: all " << checks.size() << " checks within tolerance\n";
    return true;
  }
  std::cerr << "coatfft: validate-frf: FAILED: " << failed << '\n';
  return false;
}

}  // namespace coatfft::cli
