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
  BuiltOperator built = build_scene_operator(scene, [&](const auto& body) {
    return make_operator(scene.grid, body, scene.method.options);
  });
  refuse_untrustworthy(built.report);
  return built;
}

void refuse_untrustworthy(const OperatorReport& report, std::string_view who) {
  const std::optional<double> error = report.predicted_error;
  COATFFT_REQUIRE(!error || *error <= pipeline_refusal_error, who, " = \"",
                  to_string(report.method), "\": predicted error ", *error,
                  " of max |u| on these cells with alpha = ", report.alpha.value_or(0),
                  " (docs/theory.md 4.6): the result would be meaningless; use \"frf-split\" "
                  "(exact on any cells) or square cells and a larger alpha");
}

std::vector<std::string> operator_warnings(const OperatorReport& report) {
  std::vector<std::string> warnings;
  if (report.predicted_error && *report.predicted_error > pipeline_warning_error)
    warnings.push_back(detail::concat(
        "method ", to_string(report.method), ": predicted error ", *report.predicted_error,
        " of max |u| (periodisation of the FRF pipelines at alpha = ", report.alpha.value_or(0),
        ", docs/theory.md 4.6); \"frf-split\" is exact, or raise alpha"));
  return warnings;
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
