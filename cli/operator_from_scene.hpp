#pragma once
// The scene's operator: make_operator on the scene's grid, body and [method] options, with the
// FFTW wisdom file of [method] loaded before and saved after; and the operator's report as the
// keys of summary.json.
#include <nlohmann/json.hpp>

#include "cli/scene.hpp"
#include "convolution/make_operator.hpp"

namespace coatfft::cli {

/// Throws InvalidArgument when the method cannot handle the body (e.g. Love DC-FFT on a coating).
BuiltOperator operator_from_scene(const Scene& scene);

/// The method-specific keys of summary.json: frf, alpha, g0, g0_method, g0_seconds,
/// g0_estimated_error (an omitted g(0) is reported as null), split_beta, split_seconds.
nlohmann::json operator_report_json(const OperatorReport& report);

}  // namespace coatfft::cli
