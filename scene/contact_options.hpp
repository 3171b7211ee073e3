#pragma once
// The contact solver's options of a [contact] scene (contact/contact_solver.hpp): shared by the
// serial run (scene/scene_run.hpp) and the distributed one (scene/distributed_run.hpp).
#include "contact/contact_solver.hpp"
#include "scene/progress_observer.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// The contact solver's options of a [contact] scene, its iterations reported to `progress`
/// (which must outlive the solver).
ContactOptions solver_options(const ContactSpec& spec, int threads, ProgressObserver& progress);

}  // namespace coatfft::scene
