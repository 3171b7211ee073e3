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
#include "cli/run_outputs.hpp"
#include "cli/signal_cleanup.hpp"
#include "cli/staged_output.hpp"
#include "cli/wisdom_file.hpp"
#include "core/detail/close_written.hpp"
#include "core/error.hpp"
#include "io/npy.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/scene.hpp"
#include "scene/scene_netcdf.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::cli {

namespace {

void write_displacement_csv(const std::filesystem::path& path, const Grid& grid, const Field& p,
                            const Field& uz) {
  std::ofstream out(path);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  write_displacement_rows(out, grid, 0, p, uz, true);
  detail::close_written(out, path);
}

// stress.npy (n_depths, 6, ny, nx), von_mises.npy (n_depths, ny, nx), stress_section.npy
// (nz, 6, nx), von_mises_section.npy (nz, nx), stress_interfaces.npy (n_interfaces, 2, 6, ny, nx),
// von_mises_interfaces.npy (n_interfaces, 2, ny, nx): docs/stress.md.
void write_stress_outputs(StagedOutput& out, const scene::OutputSpec& spec, const Grid& grid,
                          const scene::StressRun& s) {
  const auto nx = static_cast<std::size_t>(grid.nx()), ny = static_cast<std::size_t>(grid.ny());
  const std::size_t n = s.depth_planes;
  if (spec.stress)
    io::write_npy_array(out.path("stress.npy"), std::vector<std::size_t>{n, 6, ny, nx}, s.stress);
  if (spec.von_mises)
    io::write_npy_array(out.path("von_mises.npy"), std::vector<std::size_t>{n, ny, nx},
                        s.von_mises);
  const std::size_t nz = s.section_rows;
  if (spec.stress_section)
    io::write_npy_array(out.path("stress_section.npy"), std::vector<std::size_t>{nz, 6, nx},
                        s.section);
  if (spec.von_mises_section)
    io::write_npy_array(out.path("von_mises_section.npy"), std::vector<std::size_t>{nz, nx},
                        s.section_von_mises);
  const std::size_t ni = s.interface_count;
  if (spec.stress_interfaces)
    io::write_npy_array(out.path("stress_interfaces.npy"),
                        std::vector<std::size_t>{ni, 2, 6, ny, nx}, s.interfaces);
  if (spec.von_mises_interfaces)
    io::write_npy_array(out.path("von_mises_interfaces.npy"),
                        std::vector<std::size_t>{ni, 2, ny, nx}, s.interfaces_von_mises);
}

// The fields of a sweep, one per value, as one array (n_values, ny, nx).
void write_stacked(const std::filesystem::path& path, const std::vector<Field>& fields) {
  const std::vector<double> values = scene::stacked_fields(fields);
  const std::size_t shape[3] = {fields.size(), static_cast<std::size_t>(fields.front().cols()),
                                static_cast<std::size_t>(fields.front().rows())};
  io::write_npy_array(path, shape, values);
}

// A field per step: one step's as it is (ny, nx), a path's stacked (n_steps, ny, nx).
void write_steps(const std::filesystem::path& path, const std::vector<Field>& fields,
                 bool path_run) {
  if (path_run)
    write_stacked(path, fields);
  else
    io::write_npy(path, fields.back());
}

// stick.npy: uint8, (ny, nx) or stacked (n_steps, ny, nx).
void write_stick(const std::filesystem::path& path, const std::vector<StickMask>& masks,
                 bool path_run) {
  std::vector<std::uint8_t> bytes;
  for (std::size_t k = path_run ? 0 : masks.size() - 1; k < masks.size(); ++k)
    bytes.insert(bytes.end(), masks[k].data(), masks[k].data() + masks[k].size());
  std::vector<std::size_t> shape = {static_cast<std::size_t>(masks.back().cols()),
                                    static_cast<std::size_t>(masks.back().rows())};
  if (path_run) shape.insert(shape.begin(), masks.size());
  io::write_npy_bytes(path, shape, bytes);
}

// A partial slip's files (scene/scene.hpp, OutputSpec::shear, stick, slip).
void write_partial_slip(StagedOutput& out, const scene::OutputSpec& spec,
                        const scene::PartialSlipFields& f, bool path_run) {
  if (spec.shear) {
    write_steps(out.path("shear_x.npy"), f.shear_x, path_run);
    write_steps(out.path("shear_y.npy"), f.shear_y, path_run);
  }
  if (spec.stick) write_stick(out.path("stick.npy"), f.stick, path_run);
  if (spec.slip) {
    write_steps(out.path("slip_x.npy"), f.slip_x, path_run);
    write_steps(out.path("slip_y.npy"), f.slip_y, path_run);
  }
}

// The .npy files: a sweep's uz, pressure, gap and plastic depth stacked, else one field each;
// the residual gap; stresses; ux, uy.
void write_npy_outputs(StagedOutput& out, const scene::OutputSpec& spec,
                       const scene::SceneRun& run) {
  if (run.sweep) {
    if (spec.uz) write_stacked(out.path("uz.npy"), run.sweep->uz);
    if (spec.pressure) write_stacked(out.path("pressure.npy"), run.sweep->pressure);
    if (spec.gap) write_stacked(out.path("gap.npy"), run.sweep->gap);
    if (spec.plastic) write_stacked(out.path("plastic.npy"), run.sweep->plastic);
  } else {
    if (spec.uz) io::write_npy(out.path("uz.npy"), run.uz);
    if (spec.pressure) io::write_npy(out.path("pressure.npy"), run.pressure);
    if (spec.gap && run.gap) io::write_npy(out.path("gap.npy"), *run.gap);
    if (spec.plastic && run.plastic) io::write_npy(out.path("plastic.npy"), *run.plastic);
  }
  if (spec.residual_gap && run.residual_gap)
    io::write_npy(out.path("residual_gap.npy"), *run.residual_gap);
  if (run.stress) write_stress_outputs(out, spec, run.grid, *run.stress);
  if (spec.in_plane && spec.ux && run.ux) io::write_npy(out.path("ux.npy"), *run.ux);
  if (spec.in_plane && spec.uy && run.uy) io::write_npy(out.path("uy.npy"), *run.uy);
  if (run.partial_slip) write_partial_slip(out, spec, *run.partial_slip, spec.fretting);
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
    detail::close_written(csv, "sweep.csv");
  }
  if (spec.fretting) {
    std::ofstream csv(out.path("fretting.csv"));
    csv << scene::fretting_csv(run.summary["fretting"]["steps"]);
    detail::close_written(csv, "fretting.csv");
  }
  if (spec.displacement_csv)
    write_displacement_csv(out.path("displacement.csv"), run.grid, run.pressure, run.uz);
  write_summary(out.path("summary.json"), run.summary);
  out.commit();
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
  // What the run found, once its files are in place; a contact that did not converge has no
  // answer to tell (main.cpp says so), and --quiet keeps the terminal silent.
  if (run.status == scene::RunStatus::ok && !options.quiet) print_highlights(run.summary);
  return run.status;
}

}  // namespace coatfft::cli
