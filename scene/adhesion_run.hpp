#pragma once
// The adhesive contact of a [contact] scene (contact/adhesive_contact.hpp): its one value, or
// its sweep's values in the order solved (up, then with unload back down through pull-off), and
// summary.json's "adhesion".
#include <nlohmann/json.hpp>
#include <vector>

#include "contact/adhesive_contact.hpp"
#include "scene/progress_observer.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// The solves of [contact] adhesion on `solver`, each value from the state before it. A load the
/// contact cannot hold (past pull-off under load control) is refused as a [contact] key, before
/// anything is written.
std::vector<AdhesiveResult> solve_scene_adhesion(ContactSolver& solver, const Scene& scene,
                                                 const Field& height, ProgressObserver& progress);

/// summary.json's "adhesion": the law (work_of_adhesion, adhesion_range, cohesive_stress), the
/// pull-off (pull_off_load: the most tensile load seen, pull_off_approach: its approach), the
/// last solve's contact_area and cohesive_area, the rounds of all solves, jumped_off_at (the
/// approach of the first step whose contact jumped off, null if none), and for a sphere or a
/// paraboloid Maugis' lambda with the surface's (top coating's, or substrate's) modulus.
nlohmann::json report_adhesion(const std::vector<AdhesiveResult>& results, const Scene& scene);

}  // namespace coatfft::scene
