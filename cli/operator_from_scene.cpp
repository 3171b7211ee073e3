#include "cli/operator_from_scene.hpp"

#include <string>

#include "convolution/fftw_wisdom.hpp"

namespace coatfft::cli {

BuiltOperator operator_from_scene(const Scene& scene) {
  const MethodSpec& method = scene.method;
  if (!method.wisdom.empty()) load_fftw_wisdom(method.wisdom.string());
  BuiltOperator built = make_operator(scene.grid, scene.body, method.options);
  if (!method.wisdom.empty()) save_fftw_wisdom(method.wisdom.string());
  return built;
}

nlohmann::json operator_report_json(const OperatorReport& report) {
  nlohmann::json json = nlohmann::json::object();
  if (!report.frf.empty()) json["frf"] = report.frf;
  if (report.g0) {
    // An omitted g(0) is no value at all (the operator uses 0 in its place): reported as null.
    const G0Result& g0 = *report.g0;
    const bool omitted = g0.method == G0Method::omitted;
    json["g0"] = omitted ? nlohmann::json() : nlohmann::json(g0.value);
    json["g0_method"] = std::string(to_string(g0.method));
    json["g0_seconds"] = g0.seconds;
    json["g0_estimated_error"] = omitted ? nlohmann::json() : nlohmann::json(g0.estimated_error);
  }
  if (report.alpha) json["alpha"] = *report.alpha;
  if (report.split) {
    json["split_beta"] = report.split->beta;
    json["split_seconds"] = report.split->seconds;
  }
  return json;
}

}  // namespace coatfft::cli
