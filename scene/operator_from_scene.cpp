#include "scene/operator_from_scene.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::scene {

namespace fs = std::filesystem;

std::string read_wisdom_file(const fs::path& path) {
  constexpr std::uintmax_t max_wisdom_bytes = 64 << 20;
  return io::read_input_file(path, "an FFTW wisdom file", max_wisdom_bytes);
}

bool holds_fftw_wisdom(const std::string& text) {
  return text.rfind("(fftw-3", 0) == 0;
}

// The periodic kernel's refusal of an FRF it cannot sum names the library's terms (its remainder,
// c_inf); in a scene the cause is the thinnest coating against the cells: named by its key.
void refuse_periodic_kernel(const Scene& scene, const LayerStack& body,
                            const std::string& message) {
  const auto& coatings = body.coatings();
  const auto thinnest = std::min_element(
      coatings.begin(), coatings.end(),
      [](const Coating& a, const Coating& b) { return a.thickness < b.thickness; });
  if (thinnest == coatings.end()) throw InvalidArgument(message);
  throw InvalidArgument(detail::concat(
      "[[coating]] ", thinnest - coatings.begin() + 1, " thickness = ", thinnest->thickness,
      " m, against cells of ", std::min(scene.grid.dx(), scene.grid.dy()),
      " m on a periodic boundary: ", message,
      "; leave the coating out, or use [method] name = \"auto\", which leaves out a coating "
      "thinner than a hundredth of a cell where its effect is within the tolerance"));
}

BuiltOperator operator_from_scene(const Scene& scene) {
  // The plan is resolve_automatic_method's, held in scene.method: its options, and the body
  // build_scene_operator picks (the reduced one, if any).
  const OperatorPlan plan{scene.method.options, std::nullopt, {}, std::nullopt};
  return build_scene_operator(scene, [&](const auto& body) {
    return build_operator(scene.grid, body, plan, "[method] name");
  });
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
  if (report.predicted_error) json["predicted_error"] = *report.predicted_error;
  if (report.split) {
    json["split_beta"] = report.split->beta;
    json["split_seconds"] = report.split->seconds;
  }
  return json;
}

}  // namespace coatfft::scene
