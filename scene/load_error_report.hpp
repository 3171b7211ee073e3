#pragma once
// The load's own discretisation error in summary.json (docs/theory.md 4.7): "load_discretization"
// for analytic loads (hertz, uniform_disk), estimated with the scene's own operator by one extra
// application; and "refinement", what [grid] refine = "auto" chose.
#include <nlohmann/json.hpp>

#include "convolution/operators/surface_operator.hpp"
#include "loads/discretization_error.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// {"estimated_error": max |u_cellwise - u_continuous| / max |u| (estimated), "absolute_error"
/// [m], "sampling"} of an estimate
/// (scene/row_layout.cpp makes it, on the rows a run holds).
nlohmann::json load_discretization_json(const PressureSpec& load,
                                        const LoadDiscretizationEstimate& estimate);

/// {"tolerance_total", "load_tolerance", "operator_tolerance", "estimate", "tried": [{nx, ny,
/// estimate}]}, or null without refine = "auto".
nlohmann::json refinement_json(const Scene& scene);

}  // namespace coatfft::scene
