#pragma once
// The scene's operator: the library's build_operator (model/operator_plan.hpp) on the scene's
// grid, body and [method] options as planned by resolve_automatic_method (which writes no file:
// the program loads and saves the FFTW wisdom file around it, cli/wisdom_file.hpp), and the
// operator's report as the keys of summary.json.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "model/operator_plan.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// The text of the FFTW wisdom file at `path` (at most 64 MiB: wisdom of a few hundred plans is
/// tens of kilobytes; a FIFO or a device is refused, io/input_file.hpp).
std::string read_wisdom_file(const std::filesystem::path& path);
/// Whether `text` is FFTW wisdom, by its first characters.
bool holds_fftw_wisdom(const std::string& text);

/// Throws the periodic kernel's refusal `message` of `body` in the scene's terms: the thinnest
/// coating's key, its thickness against the cells, and what to do.
[[noreturn]] void refuse_periodic_kernel(const Scene& scene, const LayerStack& body,
                                         const std::string& message);

/// `factory(body or frf)` (make_operator's, or make_distributed_operator's, on the scene's grid
/// and options) on the body it builds for: a table body's FRF, else the body name = "auto" may
/// have reduced (scene/automatic_method.hpp). The periodic kernel's refusal is rethrown by
/// refuse_periodic_kernel.
template <typename Factory>
auto build_scene_operator(const Scene& scene, Factory&& factory) {
  const LayerStack* body = scene.method.reduced_body ? &*scene.method.reduced_body
                           : scene.body              ? &*scene.body
                                                     : nullptr;
  try {
    return scene.frf ? factory(*scene.frf) : factory(*body);
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    if (scene.frf || message.rfind("periodic kernel:", 0) != 0) throw;
    refuse_periodic_kernel(scene, *body, message);
  }
}

/// Builds the operator (the library's build_operator, model/operator_plan.hpp, by
/// build_scene_operator). Throws InvalidArgument when the method cannot handle the body (e.g. Love
/// DC-FFT on a coating), and when an FRF pipeline's predicted error exceeds
/// pipeline_refusal_error.
BuiltOperator operator_from_scene(const Scene& scene);

/// The method-specific keys of summary.json: frf, alpha, g0, g0_method, g0_seconds,
/// g0_estimated_error (an omitted g(0) is reported as null), split_beta, split_seconds.
nlohmann::json operator_report_json(const OperatorReport& report);

}  // namespace coatfft::scene
