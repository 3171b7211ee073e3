#include "cli/validate_frf_command.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "frf/tabulated_frf.hpp"
#include "scene/frf_validation.hpp"
#include "scene/resources.hpp"
#include "scene/scene.hpp"

namespace coatfft::cli {

namespace {

// The scene's [pressure], when it is one of the two loads of the checks, replaces that load; the
// operators get the threads of [method].
scene::FrfValidationOptions validation_options(const scene::Scene& scene) {
  scene::FrfValidationOptions options;
  options.threads = scene.method.options.threads;
  if (scene.pressure && scene.pressure->kind != scene::PressureKind::file)
    options.load =
        scene::FrfCheckLoad{axisymmetric_shape(*scene.pressure), scene.pressure->amplitude,
                            scene.pressure->radius, scene.pressure->sampling};
  return options;
}

void print_report(const scene::Scene& scene, const TabulatedFrf& table,
                  const scene::FrfValidation& result) {
  std::cout << "validate-frf: [frf] " << scene.frf_file.string() << " (" << table.size()
            << " points, k = " << table.k().front() << " to " << table.k().back()
            << " rad/m) against " << result.reference << "\n";
  std::cout << std::left << std::setw(26) << "check" << std::setw(12) << "max rel diff"
            << std::setw(39) << "  at" << std::setw(11) << "tolerance"
            << "result    reference\n";
  for (const scene::FrfCheck& c : result.checks) {
    std::ostringstream diff, tol;
    diff << std::scientific << std::setprecision(2) << c.difference;
    tol << std::scientific << std::setprecision(1) << c.tolerance;
    std::cout << std::setw(26) << c.name << std::setw(12) << diff.str() << "  " << std::setw(36)
              << c.detail << ' ' << std::setw(11) << tol.str() << std::setw(10)
              << (c.passed ? "ok" : "FAILED") << c.reference << '\n';
  }
}

}  // namespace

bool validate_frf_command(const ValidateFrfOptions& options) {
  // Before the scene: a bad tolerance is refused whatever the scene holds.
  scene::check_validation_tolerance(options.tolerance);
  const scene::Scene scene = scene::read_scene(options.scene);
  const auto* table = dynamic_cast<const TabulatedFrf*>(scene.frf.get());
  COATFFT_REQUIRE(table != nullptr, options.scene.string(),
                  ": no [frf] section, so no table to validate (validate-frf checks a body given "
                  "as a table against its [substrate] and [[coating]])");
  COATFFT_REQUIRE(scene.body.has_value(), options.scene.string(),
                  ": no [substrate], so nothing to validate the [frf] table against; describe the "
                  "body the table claims to be with [substrate] (and [[coating]])");
  scene::check_memory(scene, std::nullopt);
  const scene::FrfValidation result = scene::validate_frf(
      *table, *scene.body, scene.grid, options.tolerance, validation_options(scene));
  print_report(scene, *table, result);
  std::string failed;
  for (const scene::FrfCheck& c : result.checks)
    if (!c.passed) failed += (failed.empty() ? "" : ", ") + c.name;
  if (result.passed) {
    std::cout << "validate-frf: all " << result.checks.size() << " checks within tolerance\n";
    return true;
  }
  std::cerr << "coatfft: validate-frf: FAILED: " << failed << '\n';
  return false;
}

}  // namespace coatfft::cli
