#include "cli/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/progress.hpp"
#include "cli/signal_cleanup.hpp"
#include "cli/staged_output.hpp"
#include "cli/wisdom_file.hpp"
#include "core/error.hpp"
#include "scene/npy.hpp"
#ifdef COATFFT_WITH_MPI
#include "scene/distributed_run.hpp"
#include "scene/npy_slab.hpp"
#endif
#include "scene/operator_from_scene.hpp"
#include "scene/scene.hpp"
#include "scene/scene_netcdf.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::cli {

namespace {

// displacement.csv's lines of the rows y0 <= j < y0 + p.cols() (p and uz hold those rows), after
// its header when `header`.
void write_displacement_rows(std::ostream& out, const Grid& grid, std::ptrdiff_t y0, const Field& p,
                             const Field& uz, bool header) {
  if (header) out << "x,y,pressure,uz\n";
  out << std::setprecision(17);
  for (Eigen::Index j = 0; j < p.cols(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i)
      out << grid.x(i) << ',' << grid.y(y0 + j) << ',' << p(i, j) << ',' << uz(i, j) << '\n';
}

void write_displacement_csv(const std::filesystem::path& path, const Grid& grid, const Field& p,
                            const Field& uz) {
  std::ofstream out(path);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  write_displacement_rows(out, grid, 0, p, uz, true);
  COATFFT_REQUIRE(out.good(), "failed writing ", path.string());
}

// The files a run writes, in the order of the manifest (cli/staged_output.hpp). Only these are
// checked, staged and committed.
// With format = "netcdf", the .npy files' arrays go into one file instead, named in the place of
// the first of them.
std::vector<std::string> output_names(const scene::OutputSpec& spec) {
  std::vector<std::string> names;
  if (spec.uz) names.push_back("uz.npy");
  if (spec.pressure) names.push_back("pressure.npy");
  if (spec.displacement_csv) names.push_back("displacement.csv");
  names.push_back("summary.json");
  if (spec.gap) names.push_back("gap.npy");
  if (spec.sweep) names.push_back("sweep.csv");
  if (spec.in_plane) names.insert(names.end(), {"ux.npy", "uy.npy"});
  if (spec.stress) names.push_back("stress.npy");
  if (spec.von_mises) names.push_back("von_mises.npy");
  if (spec.stress_section) names.push_back("stress_section.npy");
  if (spec.von_mises_section) names.push_back("von_mises_section.npy");
  if (!spec.netcdf) return names;
  const auto is_npy = [](const std::string& name) { return name.ends_with(".npy"); };
  const auto first = std::find_if(names.begin(), names.end(), is_npy);
  if (first == names.end()) return names;
  *first = scene::netcdf_output_name;
  names.erase(std::remove_if(first + 1, names.end(), is_npy), names.end());
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// stress.npy (n_depths, 6, ny, nx), von_mises.npy (n_depths, ny, nx), stress_section.npy
// (nz, 6, nx), von_mises_section.npy (nz, nx): docs/stress.md.
void write_stress_outputs(StagedOutput& out, const scene::OutputSpec& spec, const Grid& grid,
                          const scene::StressRun& s) {
  const auto nx = static_cast<std::size_t>(grid.nx()), ny = static_cast<std::size_t>(grid.ny());
  const std::size_t n = s.von_mises.size() / (nx * ny);
  if (spec.stress)
    scene::write_npy_array(out.path("stress.npy"), std::vector<std::size_t>{n, 6, ny, nx},
                           s.stress);
  if (spec.von_mises)
    scene::write_npy_array(out.path("von_mises.npy"), std::vector<std::size_t>{n, ny, nx},
                           s.von_mises);
  const std::size_t nz = s.section_von_mises.size() / nx;
  if (spec.stress_section)
    scene::write_npy_array(out.path("stress_section.npy"), std::vector<std::size_t>{nz, 6, nx},
                           s.section);
  if (spec.von_mises_section)
    scene::write_npy_array(out.path("von_mises_section.npy"), std::vector<std::size_t>{nz, nx},
                           s.section_von_mises);
}

// The fields of a sweep, one per value, as one array (n_values, ny, nx).
void write_stacked(const std::filesystem::path& path, const std::vector<Field>& fields) {
  const std::vector<double> values = scene::stacked_fields(fields);
  const std::size_t shape[3] = {fields.size(), static_cast<std::size_t>(fields.front().cols()),
                                static_cast<std::size_t>(fields.front().rows())};
  scene::write_npy_array(path, shape, values);
}

// The .npy files: a sweep's uz, pressure and gap stacked, else one field each; stresses; ux, uy.
void write_npy_outputs(StagedOutput& out, const scene::OutputSpec& spec,
                       const scene::SceneRun& run) {
  if (run.sweep) {
    if (spec.uz) write_stacked(out.path("uz.npy"), run.sweep->uz);
    if (spec.pressure) write_stacked(out.path("pressure.npy"), run.sweep->pressure);
    if (spec.gap) write_stacked(out.path("gap.npy"), run.sweep->gap);
  } else {
    if (spec.uz) scene::write_npy(out.path("uz.npy"), run.uz);
    if (spec.pressure) scene::write_npy(out.path("pressure.npy"), run.pressure);
    if (spec.gap && run.gap) scene::write_npy(out.path("gap.npy"), *run.gap);
  }
  if (run.stress) write_stress_outputs(out, spec, run.grid, *run.stress);
  if (spec.in_plane && run.ux && run.uy) {
    scene::write_npy(out.path("ux.npy"), *run.ux);
    scene::write_npy(out.path("uy.npy"), *run.uy);
  }
}

void write_summary(const std::filesystem::path& path, const nlohmann::json& summary) {
  std::ofstream json(path);
  json << std::setw(2) << summary << '\n';
  COATFFT_REQUIRE(json.good(), "failed writing summary.json");
}

// Writes the requested outputs only: the CSV text, the costliest of them (a 2048^2 grid makes
// hundreds of megabytes of decimal text), is not even formatted when it is not asked for.
void write_outputs(StagedOutput& out, const scene::OutputSpec& spec, const scene::SceneRun& run,
                   Progress& progress) {
  const auto names = output_names(spec);
  progress.stage("writing " + joined(names));
  if (!spec.netcdf)
    write_npy_outputs(out, spec, run);
  else if (std::find(names.begin(), names.end(), scene::netcdf_output_name) != names.end())
    scene::write_run_netcdf(out.path(scene::netcdf_output_name), spec, run);
  if (run.sweep) {
    std::ofstream csv(out.path("sweep.csv"));
    csv << scene::sweep_csv(run.summary["sweep"]);
    COATFFT_REQUIRE(csv.good(), "failed writing sweep.csv");
  }
  if (spec.displacement_csv)
    write_displacement_csv(out.path("displacement.csv"), run.grid, run.pressure, run.uz);
  write_summary(out.path("summary.json"), run.summary);
  out.commit();
}

// Every warning of summary.json, printed on stderr as README promises: the operator's, the
// stress planes', and the contact solver's note (why it did not converge; main.cpp adds the
// exit status's line).
void print_warnings(const nlohmann::json& summary) {
  for (const auto& warning : summary["warnings"]) {
    std::cerr << "coatfft: warning: " << warning.get<std::string>() << '\n';
  }
}

}  // namespace

scene::RunStatus run_command(const RunOptions& options) {
  Progress progress(progress_wanted(options.quiet, ::isatty(STDERR_FILENO) == 1), std::cerr);
  const scene::SceneRunOptions run_options{options.repeat, options.max_memory, &progress};
  // Until the outputs are written, Ctrl-C stops the computation at its next check and the run
  // unwinds (main.cpp reports it); the checks also keep a long stage's progress line going.
  StopOnSigint stop_on_sigint([&progress] { progress.tick(); });
  scene::PreparedScene prepared = prepare_scene(options.scene, run_options);
  const scene::OutputSpec spec = prepared.scene.output;
  // Every output target is checked now, before any work: a run that cannot write is refused at
  // once, not after minutes of computing. Outputs of an earlier run that this one does not
  // write are left to the manifest (stale ones removed at the commit).
  StagedOutput out(options.outdir, output_names(spec), prepared.scene.input_files);
  // The wisdom file is loaded now and saved once everything is planned (cli/wisdom_file.hpp);
  // load_wisdom refuses one that is an input or one of OUTDIR's outputs.
  load_wisdom(prepared.scene, out);
  const std::filesystem::path wisdom = prepared.scene.method.wisdom;
  const std::vector<std::filesystem::path> inputs = prepared.scene.input_files;
  const scene::SceneRun run = compute_scene(std::move(prepared), run_options);
  save_wisdom(wisdom, inputs);
  // From here a signal ends the run at once: the staged files are removed by the handler.
  stop_on_sigint.finish();
  print_warnings(run.summary);
  write_outputs(out, spec, run, progress);
  progress.finish();
  return run.status;
}

#ifdef COATFFT_WITH_MPI
namespace {

// OUTDIR staged by rank 0 (cli/staged_output.hpp) and the staged path of each output, the same on
// every rank; rank 0's refusal is thrown on every rank.
struct DistributedOutput {
  std::unique_ptr<StagedOutput> staged;  // rank 0's (not movable)
  std::map<std::string, std::filesystem::path> paths;
};

DistributedOutput stage_on_rank_0(const Communicator& comm, const std::filesystem::path& outdir,
                                  const std::vector<std::string>& names,
                                  const std::vector<std::filesystem::path>& inputs) {
  DistributedOutput out;
  std::string refusal;
  if (comm.rank() == 0) {
    try {
      out.staged = std::make_unique<StagedOutput>(outdir, names, inputs);
    } catch (const InvalidArgument& e) {
      refusal = e.what();
    }
  }
  comm.broadcast(refusal);
  if (!refusal.empty()) throw InvalidArgument(refusal);
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
  if (spec.uz) scene::write_npy_slab(comm, path("uz.npy"), run.uz, run.slab);
  if (spec.pressure) scene::write_npy_slab(comm, path("pressure.npy"), run.pressure, run.slab);
  if (spec.gap) scene::write_npy_slab(comm, path("gap.npy"), run.gap, run.slab);
  if (spec.displacement_csv) {
    std::ostringstream text;
    write_displacement_rows(text, grid, run.slab.y0, run.pressure, run.uz, comm.rank() == 0);
    scene::write_text_slab(comm, path("displacement.csv"), text.str());
  }
  if (comm.rank() != 0) return;
  write_summary(path("summary.json"), run.summary);
  out.staged->commit();
}

}  // namespace

scene::RunStatus run_command(const RunOptions& options, const Communicator& comm) {
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  Progress progress(comm.rank() == 0 && progress_wanted(options.quiet, terminal), std::cerr);
  const scene::SceneRunOptions run_options{options.repeat, options.max_memory, &progress};
  // Ctrl-C reaches every rank (mpirun forwards it); the solver agrees on it over the ranks.
  StopOnSigint stop_on_sigint([&progress] { progress.tick(); });
  const scene::PreparedScene prepared =
      scene::prepare_distributed_scene(comm, options.scene, run_options);
  const scene::OutputSpec spec = prepared.scene.output;
  const std::vector<std::string> names = output_names(spec);
  DistributedOutput out = stage_on_rank_0(comm, options.outdir, names, prepared.scene.input_files);
  const scene::DistributedSceneRun run =
      scene::compute_distributed_scene(comm, prepared, run_options);
  stop_on_sigint.finish();
  print_warnings(run.summary);  // rank 0's: the other ranks' stderr is silenced (main.cpp)
  progress.stage("writing " + joined(names));
  write_distributed_outputs(comm, out, spec, prepared.scene.grid, run);
  progress.finish();
  return run.status;
}
#endif

}  // namespace coatfft::cli
