#include "scene/load_error_report.hpp"

#include "loads/discretization_error.hpp"

namespace coatfft::scene {

nlohmann::json load_discretization_json(const PressureSpec& load,
                                        const LoadDiscretizationEstimate& estimate) {
  return {{"estimated_error", estimate.relative_error},
          {"absolute_error", estimate.absolute_error},
          {"sampling", load.sampling == Sampling::centre ? "centre" : "cell_average"}};
}

nlohmann::json refinement_json(const Scene& scene) {
  if (!scene.refinement) return nullptr;
  const GridRefinement& r = *scene.refinement;
  nlohmann::json tried = nlohmann::json::array();
  for (const GridTrial& t : r.choice.tried)
    tried.push_back({{"nx", t.nx}, {"ny", t.ny}, {"estimate", t.estimate}});
  return {{"tolerance_total", r.tolerance_total},
          {"load_tolerance", r.choice.load_tolerance},
          {"operator_tolerance", scene.method.tolerance},
          {"estimate", r.choice.estimate},
          {"tried", tried}};
}

}  // namespace coatfft::scene
