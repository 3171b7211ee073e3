#pragma once
// `coatfft run SCENE.toml -o OUTDIR`: one displacement computation (known [pressure]) or one
// contact solve ([contact]) from a scene file.
#include <filesystem>
#include <optional>

#ifdef COATFFT_WITH_MPI
#include "distributed/communicator.hpp"
#endif
#include "scene/scene_run.hpp"  // RunStatus; what the run computes (run_scene without the writing)

namespace coatfft::cli {

struct RunOptions {
  std::filesystem::path scene;
  std::filesystem::path outdir;
  int repeat = 1;  ///< operator applications timed; apply_seconds is their median
  /// Memory the run may use [bytes] (--max-memory); by default what the machine has available.
  std::optional<double> max_memory;
  /// No progress on the terminal and no lines of what the run found (--quiet); warnings and
  /// errors are still printed.
  bool quiet = false;
};

/// Runs the scene (prepare_scene, then compute_scene: scene/scene_run.hpp) and writes the outputs
/// its [output] section asks for (by default OUTDIR/{uz.npy, pressure.npy, displacement.csv,
/// summary.json}, + gap.npy for a contact) all at once (cli/staged_output.hpp). Reports progress
/// on stderr when it is a terminal, unless quiet (cli/progress.hpp), and the operator's warnings
/// once computed; after a run that converged, unless quiet, what it found on stdout
/// (scene/run_highlights.hpp). Throws InvalidArgument on bad input, and leaves OUTDIR as it was on
/// any failure.
scene::RunStatus run_command(const RunOptions& options);

#ifdef COATFFT_WITH_MPI
/// The same on the ranks of `comm` (`mpirun -np P coatfft run`, docs/scale.md): a scene that runs
/// distributed (scene/distributed_run.hpp), every .npy and displacement.csv written by all ranks
/// into rank 0's staging folder (each its rows, MPI-IO), summary.json by rank 0, which commits.
/// Refusals are the same on every rank; rank 0 prints.
scene::RunStatus run_command(const RunOptions& options, const Communicator& comm);
#endif

}  // namespace coatfft::cli
