#pragma once
// [method] for a scene (docs/auto.md): the reference loads that stand for the scene's load, the
// scene's operator request planned by the library (model/operator_plan.hpp: for name = "auto"
// the reduced body and the method chosen for the tolerance), and the choice's report in
// summary.json and `coatfft check`.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "model/auto_method.hpp"
#include "model/body_reduction.hpp"
#include "model/operator_plan.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Applications a contact solve is expected to make, for the cost model: the solver's Hertz
/// solves took 37-55 applications' time at 512^2-2048^2 (bench/results/contact.csv).
inline constexpr double contact_applications = 50.0;

/// The loads for which a reduction's effect is bounded: the scene's own hertz or uniform_disk
/// load; a Hertz contact of a sphere or paraboloid under the given load or approach (with the
/// substrate's and the top coating's moduli); a flat punch's disk; for any other load (a file,
/// a cylinder, a height map) a Hertz load one cell wide and one half the domain wide, the two
/// ends of the range of sizes the scene can hold.
std::vector<ReferenceLoad> reference_loads(const Scene& scene);

/// The scene's operator planned (model/operator_plan.hpp) for `applications` applications (among
/// the methods that run on the ranks of a communicator when `distributed`:
/// AutoRequest::distributed): the request's checks, and for name = "auto" the body and the method
/// chosen, written into scene.method (options; reduced_body and reduction_note when reduced).
/// Returns the choice of a free boundary's "auto". Throws InvalidArgument for a request the body
/// cannot take (Love's methods on a coated free body) and when no method meets the tolerance.
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
