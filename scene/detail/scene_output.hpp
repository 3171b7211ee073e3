#pragma once
// Private to the scene layer: the files a run writes ([output]) and the stresses it computes
// ([stress]).
#include <toml++/toml.h>

#include "scene/scene.hpp"

namespace coatfft::scene {

// [output]: the files of a scene with (`contact`) or without a [contact].
OutputSpec read_output(const toml::table& root, bool contact);

// The stress files: by default every one [stress] computes; an [output] fields list names those
// it wants, each of something [stress] computes (`spec` is empty without [stress]; `interfaces`:
// [stress] is given, on a body with an interface).
void check_stress_outputs(OutputSpec& output, const StressSpec& spec, bool interfaces);

// [stress]: planes at depth and the section y = 0. The stress kernels need the layers themselves
// (docs/theory.md 2.7), which an [frf] table does not give.
StressSpec read_stress(const toml::table& root, const Scene& scene);

}  // namespace coatfft::scene
