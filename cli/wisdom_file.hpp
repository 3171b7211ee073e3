#pragma once
// The scene's FFTW wisdom file ([method] wisdom) for `coatfft run`: loaded before the operator is
// planned and saved after the computation, so that the next run of the scene plans at once.
// Building an operator writes no file; only the program writes this one.
#include <filesystem>
#include <vector>

#include "cli/staged_output.hpp"
#include "scene/scene.hpp"

namespace coatfft::cli {

/// Checks and imports the scene's FFTW wisdom file, if it names one. The wisdom file is neither
/// an input nor an output of the run (refused when it is the scene, a file the scene reads, or
/// one of `out`'s files), and an existing file must be a regular file holding FFTW wisdom: a
/// file of any other kind is never overwritten. Wisdom that FFTW cannot import (another FFTW
/// version) is reported on stderr and replaced by save_wisdom.
void load_wisdom(const scene::Scene& scene, const StagedOutput& out);

/// Saves the process's accumulated FFTW wisdom to `wisdom` (atomically; nothing when empty),
/// which load_wisdom checked; `inputs` are the run's input files, never overwritten.
void save_wisdom(const std::filesystem::path& wisdom,
                 const std::vector<std::filesystem::path>& inputs);

}  // namespace coatfft::cli
