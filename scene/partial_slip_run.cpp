#include "scene/partial_slip_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace coatfft::scene {

std::vector<PartialSlipResult> solve_scene_partial_slip(ContactSolver& solver,
                                                        RelativeSurfaceResponse& response,
                                                        const ContactSpec& spec,
                                                        const Field& height,
                                                        ProgressObserver& progress) {
  PartialSlipOptions options;
  options.friction = spec.friction;
  // The tangential iteration's relative change: as fine as the normal solve's, but no finer than
  // 1e-8 (docs/contact.md, "Partial slip": below, its last digits cost hundreds of iterations).
  options.tolerance = std::max(spec.tolerance, 1e-8);
  options.on_iteration = [&progress](int k, double residual) { progress.iteration(k, residual); };
  const std::size_t n = spec.tangential.size();
  const ContactControl control = spec.load ? ContactControl::load : ContactControl::approach;
  try {
    return solve_partial_slip_path(
        solver, response, height, control, spec.load ? *spec.load : *spec.approach,
        spec.tangential_control, spec.tangential, options, [&progress, n](std::size_t k) {
          progress.step(detail::concat("partial slip: step ", k + 1, " of ", n));
        });
  } catch (const InvalidArgument& e) {
    // The library names what it refuses as its own ("partial slip: tangential load ..."): in a
    // scene that is a [contact] key.
    const std::string message = e.what(), prefix = "partial slip: ";
    if (message.rfind(prefix, 0) != 0) throw;
    throw InvalidArgument("[contact] " + message.substr(prefix.size()));
  }
}

namespace {

nlohmann::json step_row(std::size_t k, const PartialSlipResult& r) {
  return {{"step", k + 1},
          {"tangential_load", r.tangential_load},
          {"tangential_shift", r.tangential_shift},
          {"stick_area", r.stick_area},
          {"slip_area", r.slip_area},
          {"max_shear", r.max_shear},
          {"dissipated_energy", r.dissipated_energy},
          {"iterations", r.iterations},
          {"converged", r.converged}};
}

nlohmann::json last_step(const PartialSlipResult& r, int applications) {
  return {{"tangential_load", r.tangential_load},
          {"lateral_load", r.lateral_load},
          {"tangential_shift", r.tangential_shift},
          {"stick_area", r.stick_area},
          {"stick_radius", std::sqrt(r.stick_area / std::numbers::pi)},
          {"slip_area", r.slip_area},
          {"max_shear", r.max_shear},
          {"dissipated_energy", r.dissipated_energy},
          {"iterations", r.iterations},
          {"operator_applications", applications},
          {"coupling_solves", r.coupling_solves}};
}

}  // namespace

nlohmann::json closed_loops(const std::vector<double>& values,
                            const std::vector<double>& dissipated_energy) {
  // The reversals: the steps after which the path turns back.
  std::vector<std::size_t> turns;
  for (std::size_t k = 1; k + 1 < values.size(); ++k)
    if ((values[k] - values[k - 1]) * (values[k + 1] - values[k]) < 0.0) turns.push_back(k);
  double range = 0.0;
  for (const double v : values) range = std::max(range, std::abs(v));
  nlohmann::json loops = nlohmann::json::array();
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    const std::size_t from = turns[i], mid = turns[i + 1];
    // After the second reversal the path comes back: the loop closes at the first step that
    // reaches (or passes) the first reversal's value again.
    for (std::size_t k = mid + 1; k < values.size(); ++k) {
      const bool back = (values[from] - values[mid]) * (values[k] - values[from]) >=
                        -1e-12 * range * std::abs(values[from] - values[mid]);
      if (!back) continue;
      loops.push_back({{"from_step", from + 1},
                       {"to_step", k + 1},
                       {"amplitude", 0.5 * std::abs(values[from] - values[mid])},
                       {"energy", dissipated_energy[k] - dissipated_energy[from]}});
      break;
    }
  }
  return loops;
}

PartialSlipReport report_partial_slip(std::vector<PartialSlipResult>& steps,
                                      const ContactSpec& spec) {
  PartialSlipReport report;
  PartialSlipFields& fields = report.fields;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<double> energy;
  int applications = 0;
  std::size_t first_failed = steps.size();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    PartialSlipResult& r = steps[k];
    rows.push_back(step_row(k, r));
    energy.push_back(r.dissipated_energy);
    applications += r.operator_applications;
    if (!r.converged && first_failed == steps.size()) first_failed = k;
    fields.shear_x.push_back(std::move(r.qx));
    fields.shear_y.push_back(std::move(r.qy));
    fields.slip_x.push_back(std::move(r.slip_x));
    fields.slip_y.push_back(std::move(r.slip_y));
    fields.stick.push_back(std::move(r.stick));
  }
  const bool by_load = spec.tangential_control == TangentialControl::load;
  report.converged = first_failed == steps.size();
  report.partial_slip = last_step(steps.back(), applications);
  report.partial_slip["converged"] = report.converged;
  report.partial_slip["control"] = by_load ? "tangential_load" : "tangential_shift";
  if (spec.tangential_path)
    report.fretting = {{"steps", rows}, {"loops", closed_loops(spec.tangential, energy)}};
  if (!report.converged)
    report.warning = detail::concat(
        "partial slip: step ", first_failed + 1, " of ", steps.size(), " (",
        by_load ? "tangential_load = " : "tangential_shift = ", spec.tangential[first_failed],
        ") did not converge: ", steps[first_failed].warning);
  return report;
}

void add_partial_slip(SceneRun& run, std::vector<PartialSlipResult>& steps,
                      const ContactSpec& spec) {
  PartialSlipReport report = report_partial_slip(steps, spec);
  run.summary["partial_slip"] = std::move(report.partial_slip);
  if (!report.fretting.is_null()) run.summary["fretting"] = std::move(report.fretting);
  run.summary["converged"] = report.converged && run.summary.value("converged", true);
  if (!report.converged) {
    run.status = RunStatus::not_converged;
    run.summary["warning"] = report.warning;
    run.summary["warnings"].push_back(report.warning);
  }
  run.partial_slip = std::move(report.fields);
}

std::string fretting_csv(const nlohmann::json& rows) {
  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "step,tangential_load,tangential_shift,stick_area,slip_area,max_shear,dissipated_energy,"
         "iterations,converged\n";
  for (const nlohmann::json& r : rows)
    csv << r["step"].get<int>() << ',' << r["tangential_load"].get<double>() << ','
        << r["tangential_shift"].get<double>() << ',' << r["stick_area"].get<double>() << ','
        << r["slip_area"].get<double>() << ',' << r["max_shear"].get<double>() << ','
        << r["dissipated_energy"].get<double>() << ',' << r["iterations"].get<int>() << ','
        << (r["converged"].get<bool>() ? 1 : 0) << '\n';
  return csv.str();
}

}  // namespace coatfft::scene
