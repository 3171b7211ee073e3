#pragma once
// Builds the displacement operator a scene's [method] asks for, on the scene's grid and body.
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/scene.hpp"
#include "convolution/surface_operator.hpp"

namespace coatfft::cli {

struct BuiltOperator {
  std::unique_ptr<SurfaceOperator> op;
  double setup_seconds = 0;  ///< wall time to build op (kernel, g(0), plans) [s]
  nlohmann::json report;     ///< method-specific facts for summary.json (g0, alpha, ...)
};

/// Throws InvalidArgument when the method cannot handle the body (e.g. Love DC-FFT on a coating).
/// The FRF pipelines that need g(0) (frf-spectral, frf-dcfft) compute it by [method] g0, except
/// for a load-controlled contact with report_approach = false: then G0Method::omitted.
BuiltOperator operator_from_scene(const Scene& scene);

}  // namespace coatfft::cli
