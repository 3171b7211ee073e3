// `coatfft run` on the ranks of an MPI launch (cli/run_command.hpp, docs/scale.md): the scene
// computed by the scene layer's distributed run, the output folder and the wisdom file handled by
// rank 0 as a serial run handles them, the fields' files written by every rank.
#include <unistd.h>

#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/progress.hpp"
#include "cli/run_command.hpp"
#include "cli/run_outputs.hpp"
#include "cli/signal_cleanup.hpp"
#include "cli/staged_output.hpp"
#include "cli/wisdom_file.hpp"
#include "core/error.hpp"
#include "distributed/fftw_mpi_wisdom.hpp"
#include "io/npy_slab.hpp"
#include "scene/distributed_run.hpp"
#include "scene/netcdf_slab.hpp"
#include "scene/scene_netcdf.hpp"

namespace coatfft::cli {

namespace {

// Runs `step` on rank 0 only; its refusal (InvalidArgument) is thrown on every rank, so that no
// rank waits in a collective step for one that stopped.
void on_rank_0(const Communicator& comm, const std::function<void()>& step) {
  std::string refusal;
  if (comm.rank() == 0) {
    try {
      step();
    } catch (const InvalidArgument& e) {
      refusal = e.what();
    }
  }
  comm.broadcast(refusal);
  if (!refusal.empty()) throw InvalidArgument(refusal);
}

// OUTDIR staged by rank 0 (cli/staged_output.hpp) and the staged path of each output, the same on
// every rank.
struct DistributedOutput {
  std::unique_ptr<StagedOutput> staged;  // rank 0's (not movable)
  std::map<std::string, std::filesystem::path> paths;
};

DistributedOutput stage_on_rank_0(const Communicator& comm, const std::filesystem::path& outdir,
                                  const std::vector<std::string>& names,
                                  const std::vector<std::filesystem::path>& inputs) {
  DistributedOutput out;
  on_rank_0(comm, [&] { out.staged = std::make_unique<StagedOutput>(outdir, names, inputs); });
  for (const std::string& name : names) {
    std::string path = comm.rank() == 0 ? out.staged->path(name).string() : std::string();
    comm.broadcast(path);
    out.paths[name] = path;
  }
  return out;
}

// The fields' files written by every rank (its rows), summary.json by rank 0, which commits.
void write_distributed_outputs(const Communicator& comm, DistributedOutput& out,
                               const scene::OutputSpec& spec, const Grid& grid,
                               const scene::DistributedSceneRun& run) {
  const auto path = [&out](const char* name) { return out.paths.at(name); };
  if (spec.netcdf) {
    if (out.paths.contains(scene::netcdf_output_name))
      scene::write_run_netcdf_slab(comm, path(scene::netcdf_output_name), spec, grid, run);
  } else {
    if (spec.uz) io::write_npy_slab(comm, path("uz.npy"), run.uz, run.slab);
    if (spec.pressure) io::write_npy_slab(comm, path("pressure.npy"), run.pressure, run.slab);
    if (spec.gap) io::write_npy_slab(comm, path("gap.npy"), run.gap, run.slab);
  }
  if (spec.displacement_csv) {
    std::ostringstream text;
    write_displacement_rows(text, grid, run.slab.y0, run.pressure, run.uz, comm.rank() == 0);
    io::write_text_slab(comm, path("displacement.csv"), text.str());
  }
  on_rank_0(comm, [&] {
    write_summary(path("summary.json"), run.summary);
    out.staged->commit();
  });
}

}  // namespace

scene::RunStatus run_command(const RunOptions& options, const Communicator& comm) {
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  Progress progress(comm.rank() == 0 && progress_wanted(options.quiet, terminal), std::cerr);
  const scene::SceneRunOptions run_options{options.repeat, options.max_memory, &progress};
  // Open MPI's mpirun turns Ctrl-C into SIGTERM for every rank, which ends each at once (rank 0's
  // staging folder removed, cli/signal_cleanup.hpp); a SIGINT sent to the ranks themselves stops
  // the solve at its next iteration, the ranks agreeing on it.
  StopOnSigint stop_on_sigint([&progress] { progress.tick(); });
  const scene::PreparedScene prepared =
      scene::prepare_distributed_scene(comm, options.scene, run_options);
  const scene::Scene& scene = prepared.scene;
  const std::vector<std::string> names = output_names(scene.output);
  DistributedOutput out = stage_on_rank_0(comm, options.outdir, names, scene.input_files);
  // The wisdom file is read and written by rank 0 (cli/wisdom_file.hpp); the ranks share what it
  // holds before planning and what they planned before it is saved (FFTW's MPI wisdom).
  on_rank_0(comm, [&] { load_wisdom(scene, *out.staged); });
  broadcast_fftw_wisdom(comm);
  const scene::DistributedSceneRun run =
      scene::compute_distributed_scene(comm, prepared, run_options);
  gather_fftw_wisdom(comm);
  on_rank_0(comm, [&] { save_wisdom(scene.method.wisdom, scene.input_files); });
  stop_on_sigint.finish();
  print_warnings(run.summary);  // rank 0's: the other ranks' stderr is silenced (main.cpp)
  progress.stage("writing " + joined(names));
  write_distributed_outputs(comm, out, scene.output, scene.grid, run);
  progress.finish();
  // What the run found, as the serial run prints it (cli/run_command.cpp), by rank 0 alone.
  if (comm.rank() == 0 && run.status == scene::RunStatus::ok && !options.quiet)
    print_highlights(run.summary);
  return run.status;
}

}  // namespace coatfft::cli
