#pragma once
// The partial slip of a [contact] scene (contact/partial_slip.hpp): its steps solved in the order
// given, and what the run reports of them -- the fields of every step, summary.json's
// "partial_slip" (the last step) and, for a path, "fretting" (a row per step, the closed loops and
// their energy).
#include <vector>

#include "contact/partial_slip.hpp"
#include "scene/progress_observer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::scene {

/// The steps of [contact] tangential_load or tangential_shift from rest, on `solver` (the normal
/// problem) and `response` (the body's surface relative to the indenter's). A value out of reach
/// (|Q| >= mu P under approach control) is refused as a [contact] key.
std::vector<PartialSlipResult> solve_scene_partial_slip(ContactSolver& solver,
                                                        RelativeSurfaceResponse& response,
                                                        const ContactSpec& spec,
                                                        const Field& height,
                                                        ProgressObserver& progress);

/// What a partial slip reports: every step's fields (moved from the steps), summary.json's
/// "partial_slip" (the last step's numbers, the applications of all) and, for a path,
/// "fretting" ({"steps": a row per step as fretting.csv's, "loops": closed_loops}), and whether
/// every step converged (else `warning` names the first that did not).
struct PartialSlipReport {
  PartialSlipFields fields;
  nlohmann::json partial_slip;
  nlohmann::json fretting;  ///< null for one value
  bool converged = true;
  std::string warning;
};
PartialSlipReport report_partial_slip(std::vector<PartialSlipResult>& steps,
                                      const ContactSpec& spec);

/// report_partial_slip into the run: run.partial_slip, the summary's "partial_slip" and
/// "fretting"; the run converged only when every step did (else run.status is not_converged and
/// the warning is the summary's).
void add_partial_slip(SceneRun& run, std::vector<PartialSlipResult>& steps,
                      const ContactSpec& spec);

/// The closed loops of a path of tangential values: a loop runs from a reversal to the reversal
/// two after it when the path comes back there to the value it reversed at (a full cycle), its
/// energy the friction work in between. Each: {"from_step", "to_step", "amplitude" (half the
/// range), "energy"}; steps numbered from 1 as in fretting.csv.
nlohmann::json closed_loops(const std::vector<double>& values,
                            const std::vector<double>& dissipated_energy);

}  // namespace coatfft::scene
