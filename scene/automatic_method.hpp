#pragma once
// [method] name = "auto" for a scene (docs/auto.md): the reference loads that stand for the
// scene's load, the reduced body (model/body_reduction.hpp) and the method chosen for the
// tolerance (model/auto_method.hpp), and their report in summary.json and `coatfft check`.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "model/auto_method.hpp"
#include "model/body_reduction.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Applications a contact solve is expected to make, for the cost model: the solver's Hertz
/// solves took 37-55 applications' time at 512^2-2048^2 (bench/results/contact.csv).
inline constexpr double contact_applications = 50.0;

/// Share of the tolerance a reduced body may use; the operator gets the rest.
/// The operator's own predicted error is at most a tenth of the tolerance (frf-split's kernel
/// tolerance is set so; Love's methods are exact), so a reduction may use nine tenths.
inline constexpr double reduction_share = 0.9;

struct AutomaticChoice {
  std::vector<ReferenceLoad> reference_loads;  ///< what the reduction's effect was bounded for
  std::optional<BodyReduction> reduction;      ///< none for a table body
  MethodChoice method;
  double applications = 1.0;
};

/// The loads for which a reduction's effect is bounded: the scene's own hertz or uniform_disk
/// load; a Hertz contact of a sphere or paraboloid under the given load or approach (with the
/// substrate's and the top coating's moduli); a flat punch's disk; for any other load (a file,
/// a cylinder, a height map) a Hertz load one cell wide and one half the domain wide, the two
/// ends of the range of sizes the scene can hold.
std::vector<ReferenceLoad> reference_loads(const Scene& scene);

/// The reference loads of a load whose shape is not known (a file, a cylinder, a height map, or
/// none yet): a Hertz load one cell wide and one half the domain wide, the two ends of the range
/// of sizes the grid can hold.
std::vector<ReferenceLoad> unknown_load_references(const Grid& grid);

/// The automatic choice for a layered body on `grid`: the reduced body (reduction_share of the
/// tolerance, for `loads`), then the method for the rest of request.tolerance.
AutomaticChoice choose_automatically(const Grid& grid, const LayerStack& body,
                                     std::vector<ReferenceLoad> loads, AutoRequest request);
/// The same for a body given by its FRF alone, which is never reduced.
AutomaticChoice choose_automatically(const Grid& grid, const Frf& frf,
                                     std::vector<ReferenceLoad> loads, const AutoRequest& request);

/// For name = "auto": chooses the body and the method for `applications` applications (among
/// those that run on the ranks of a communicator when `distributed`: AutoRequest::distributed)
/// and writes them into scene.method (options; reduced_body when reduced). Nothing for a named
/// method. Throws InvalidArgument when no method meets the tolerance.
std::optional<AutomaticChoice> resolve_automatic_method(Scene& scene, double applications,
                                                        bool distributed = false);

/// The applications a run of `scene` makes, for the choice: contact_applications for a contact,
/// else the `repeat` timed applications of a known load.
double expected_applications(const Scene& scene, int repeat);

/// summary.json's "auto" object: tolerance, the method chosen and why, its predicted error and
/// times, the candidates, and the reduction with its estimated effect.
nlohmann::json automatic_choice_json(const AutomaticChoice& choice, double tolerance);

/// The cost model's prediction for the scene's method as resolved (chosen by auto or named),
/// with `applications` applications: what `coatfft check` reports as the time of a run.
MethodCandidate predicted_scene_cost(const Scene& scene, double applications);

}  // namespace coatfft::scene
