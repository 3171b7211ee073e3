#include "scene/distributed_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "distributed/detail/agreed_refusal.hpp"
#include "distributed/detail/slab_fft.hpp"
#include "distributed/distributed_contact.hpp"
#include "distributed/make_distributed_operator.hpp"
#include "io/grid_file.hpp"
#include "io/input_file.hpp"
#include "io/npy_slab.hpp"
#include "loads/discretization_error.hpp"
#include "scene/a_posteriori.hpp"
#include "scene/contact_options.hpp"
#include "scene/load_error_report.hpp"
#include "scene/operator_from_scene.hpp"
#include "scene/resources.hpp"
#include "scene/row_layout.hpp"
#include "scene/run_summary.hpp"
#include "scene/scene_pressure.hpp"

namespace coatfft::scene {

namespace {

using Clock = std::chrono::steady_clock;
using coatfft::detail::seconds_since;

// A rank's memory against the serial run's at one rank: the slab transforms keep a spectrum of
// rows and one of columns, and the preconditioner has its own (measured 132 against 113 bytes a
// cell at 4096^2, docs/scale.md).
constexpr double slab_overhead = 1.2;

// The memory a rank needs: the serial estimate's arrays shared over the ranks, with the slabs'
// overhead, and the program itself.
MemoryNeed rank_memory(int ranks, const Scene& scene) {
  MemoryNeed need = estimate_memory(scene);
  need.bytes = (need.bytes - program_bytes) * slab_overhead / ranks + program_bytes;
  return need;
}

// The first part of the scene that a distributed run refuses, or "" (check_distributable).
std::string not_distributable(const Scene& scene) {
  // "auto" on a free coated body (or FRF table) reduces the body by reference displacements
  // (model/body_reduction.hpp); on a homogeneous body or a periodic boundary it needs none.
  const bool homogeneous = scene.body && scene.body->is_homogeneous();
  if (scene.method.automatic && !homogeneous)
    return detail::concat("[method] name = \"auto\" on a free boundary of ",
                          scene.frf ? "a body given by its FRF" : "a coated body",
                          " (its choice computes reference displacements of the body; name the "
                          "method: \"frf-split\")");
  const Method method = scene.method.options.method;
  if (!scene.method.automatic && !scene.periodic() && !runs_distributed(method))
    return detail::concat("[method] name = \"", to_string(method),
                          "\" on a free boundary (there a distributed run takes \"dcfft\" or "
                          "\"frf-split\")");
  if (scene.contact) {
    const ContactSpec& contact = *scene.contact;
    if (!contact.topography.is_null())
      return "[contact] topography (a measured surface: `coatfft topography FILE --detrend ... "
             "--gap -o h.npy` writes its gap for indenter = \"height_map\", path = \"h.npy\")";
    if (!contact.sweep.empty()) return "[contact] a list of values (a sweep)";
    if (contact.partial_slip())
      return "[contact] tangential_load or tangential_shift (a partial slip)";
    if (contact.friction > 0.0) return "[contact] friction";
    if (contact.hardness) return "[contact] hardness";
    if (contact.adhesion) return "[contact] adhesion";
  }
  if (scene.shear) return "[shear]";
  if (scene.stress) return "[stress]";
  if (scene.output.in_plane) return "[output] ux, uy (the in-plane displacements)";
  return {};
}

// This rank's rows of a known load: a file's read from it, a closed form's sampled, checked as the
// serial run checks its whole field (scene_pressure).
Field slab_pressure(const Communicator& comm, const Scene& scene, const Slab& slab) {
  const PressureSpec& spec = *scene.pressure;
  Field p = spec.kind == PressureKind::file ? io::read_npy_slab(comm, spec.file, slab, "value")
                                            : sample_load_rows(scene.grid, analytic_load(spec),
                                                               spec.sampling, slab.y0, slab.rows);
  require_load(scene, !comm.all(!(p != 0.0).any()));
  return p;
}

// This rank's rows of the indenter's heights: a height map's read from its file.
Field slab_heights(const Communicator& comm, const Scene& scene, const Slab& slab) {
  const ContactSpec& spec = *scene.contact;
  if (std::holds_alternative<HeightMap>(spec.indenter))
    return io::read_npy_slab(comm, spec.height_file, slab, "height");
  return height_rows(scene.grid, spec.indenter, slab.y0, slab.rows);
}

// A slab's rows, its numbers combined over the ranks.
RowLayout slab_rows(const Communicator& comm, const Slab& slab) {
  return {slab.y0, [&comm](double value) { return comm.sum(value); },
          [&comm](double value) { return comm.max(value); }};
}

// The distributed operator of the scene's body, as operator_from_scene builds the serial one.
BuiltDistributedOperator distributed_operator(const Communicator& comm, const Scene& scene) {
  return build_scene_operator(scene, [&](const auto& body) {
    return make_distributed_operator(comm, scene.grid, body, scene.method.options);
  });
}

// What every rank's run must share: its scene file's text (by its FNV-1a digest, Fowler, Noll and
// Vo), the grid that text gives (named when it differs) and --repeat (the count of collective
// applications).
struct SceneFingerprint {
  std::uint64_t text = 0;
  std::int64_t nx = 0, ny = 0;
  double lx = 0.0, ly = 0.0;
  std::int64_t repeat = 0;
  bool operator==(const SceneFingerprint&) const = default;
};

std::uint64_t text_digest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::uint64_t digest = 14695981039346656037ULL;
  for (auto c = std::istreambuf_iterator<char>(in); c != std::istreambuf_iterator<char>(); ++c) {
    digest ^= static_cast<unsigned char>(*c);
    digest *= 1099511628211ULL;
  }
  return digest;
}

// The first rank whose fingerprint is not rank 0's, named with both scene files. Collective.
void require_same_scene(const Communicator& comm, const std::filesystem::path& scene_file,
                        const Scene& scene, int repeat) {
  const Grid& g = scene.grid;
  const SceneFingerprint mine{text_digest(scene_file), g.nx(), g.ny(), g.lx(), g.ly(), repeat};
  std::vector<SceneFingerprint> all(static_cast<std::size_t>(comm.size()));
  comm.all_gather(&mine, sizeof mine, all.data());
  const auto other =
      std::find_if(all.begin(), all.end(), [&](const auto& f) { return f != all[0]; });
  if (other == all.end()) return;
  const auto rank = static_cast<int>(other - all.begin());
  std::string first = scene_file.string(), differing = scene_file.string();
  comm.broadcast(first, 0);
  comm.broadcast(differing, rank);
  const auto grid_of = [](const SceneFingerprint& f) {
    return detail::concat(f.nx, " x ", f.ny, " cells of ", f.lx, " x ", f.ly, " m");
  };
  if (other->repeat != all[0].repeat)
    throw InvalidArgument(detail::concat("rank ", rank, " runs with --repeat ", other->repeat,
                                         ", rank 0 with --repeat ", all[0].repeat,
                                         ": every rank of a run takes the same options"));
  const std::string what =
      other->nx != all[0].nx || other->ny != all[0].ny || other->lx != all[0].lx ||
              other->ly != all[0].ly
          ? detail::concat(" has a grid of ", grid_of(*other), ", rank 0's ",
                           io::quoted_excerpt(first), " one of ", grid_of(all[0]))
          : detail::concat(" differs from rank 0's ", io::quoted_excerpt(first));
  throw InvalidArgument(detail::concat("rank ", rank, "'s scene ", io::quoted_excerpt(differing),
                                       what, ": every rank of a run reads the same scene"));
}

}  // namespace

void check_distributable(const Scene& scene) {
  const std::string part = not_distributable(scene);
  COATFFT_REQUIRE(part.empty(), part,
                  " does not run distributed yet (docs/scale.md): run this scene without mpirun");
}

PreparedScene prepare_distributed_scene(const Communicator& comm,
                                        const std::filesystem::path& scene_file,
                                        const SceneRunOptions& options) {
  // Each rank reads its own scene (an MPMD launch may give each another one): its refusal, the
  // other ranks' scenes and its memory are agreed before the ranks' first collective step.
  std::optional<Scene> scene;
  std::optional<AutomaticChoice> automatic;
  agreed_refusal(comm, [&] {
    check_repeat(options.repeat);
    scene = read_scene(scene_file, SceneReading{.height_map_values = false});
    check_distributable(*scene);
    automatic =
        resolve_automatic_method(*scene, expected_applications(*scene, options.repeat), true);
    if (scene->pressure && scene->pressure->kind == PressureKind::file)
      io::check_grid_npy(scene->pressure->file, scene->grid, "[pressure] path", "a pressure");
  });
  require_same_scene(comm, scene_file, *scene, options.repeat);
  const int sharing = comm.ranks_sharing_memory();
  agreed_refusal(comm, [&] {
    std::optional<double> limit = options.max_memory;
    if (!limit)
      if (const std::optional<double> available = available_memory()) limit = *available / sharing;
    require_memory(rank_memory(comm.size(), *scene), limit, "each rank", "--max-memory (per rank)",
                   "use fewer cells or more ranks");
  });
  return {std::move(*scene), std::move(automatic)};
}

namespace {

// The keys only a distributed run has, after the serial run's.
void add_rank_summary(nlohmann::json& summary, const Communicator& comm, const Scene& scene,
                      const DistributedOperator& op) {
  summary["ranks"] = comm.size();
  summary["estimated_memory_bytes_per_rank"] = rank_memory(comm.size(), scene).bytes;
  summary["communication_seconds"] = comm.max(op.communication_seconds());
}

// The timed applications of the serial run (scene/scene_run.cpp), their result refused on every
// rank if it overflowed.
double timed_applications(const Communicator& comm, DistributedOperator& op, const Field& pressure,
                          Field& uz, int repeat, ProgressObserver& progress) {
  progress.stage(applications_stage(repeat));
  const double seconds = coatfft::detail::time_applications(op, pressure, uz, repeat);
  // Finite inputs can still overflow (|u| ~ p L / E*), as the serial run checks.
  COATFFT_REQUIRE(comm.all(uz.allFinite()),
                  "the displacement overflows double precision: rescale the units of the load "
                  "and the moduli");
  return seconds;
}

// A known load: its rows, the timed applications, and the serial run's reports over the ranks.
DistributedSceneRun compute_pressure(const Communicator& comm, const Scene& scene,
                                     const std::optional<AutomaticChoice>& automatic,
                                     const SceneRunOptions& options, ProgressObserver& progress) {
  std::ptrdiff_t unused = 0;
  const Slab rows = detail::slab_of(comm, scene.grid.nx(), scene.grid.ny(), unused);
  Field pressure = slab_pressure(comm, scene, rows);  // before the set-up, as serially
  progress.stage(setup_stage(scene));
  auto [op, report] = distributed_operator(comm, scene);
  const Slab slab = op->slab();
  COATFFT_REQUIRE(slab.y0 == rows.y0 && slab.rows == rows.rows,
                  "distributed run: the operator's rows are not the load's");
  Field uz;
  const double apply_seconds =
      timed_applications(comm, *op, pressure, uz, options.repeat, progress);
  const RowLayout layout = slab_rows(comm, slab);
  const FieldNumbers numbers = field_numbers(scene.grid, layout, pressure, uz);
  nlohmann::json summary =
      common_summary(scene, automatic, report, apply_seconds, options.repeat, numbers);
  add_known_load_reports(summary, scene, layout, numbers, *op, pressure, uz);
  add_rank_summary(summary, comm, scene, *op);
  return {slab, std::move(pressure), std::move(uz), Field(), std::move(summary), RunStatus::ok};
}

// A contact: the heights' rows, the solve, the timed applications.
DistributedSceneRun compute_contact(const Communicator& comm, Scene scene,
                                    const std::optional<AutomaticChoice>& automatic,
                                    const SceneRunOptions& options, ProgressObserver& progress) {
  use_normal_compliance_body(scene);
  const ContactSpec& spec = *scene.contact;
  progress.stage(setup_stage(scene));
  auto [op, report] = distributed_operator(comm, scene);
  const Slab slab = op->slab();  // this rank's rows of every field
  const Field heights = slab_heights(comm, scene, slab);
  const auto solver =
      distributed_contact_solver(*op, solver_options(spec, scene.method.options.threads, progress));
  progress.stage(
      detail::concat("solving the contact (", spec.load ? "load" : "approach", " control)"));
  const auto start = Clock::now();
  ContactResult result =
      solver->solve(heights, spec.load ? ContactControl::load : ContactControl::approach,
                    spec.load ? *spec.load : *spec.approach);
  const double solve_seconds = seconds_since(start);
  COATFFT_REQUIRE(!result.touches_boundary,  // the serial run's refusal (scene/scene_run.cpp)
                  domain_edge_refusal);
  Field uz;  // only for the timing: the solver returned the displacement
  const double apply_seconds =
      timed_applications(comm, *op, result.pressure, uz, options.repeat, progress);
  const FieldNumbers numbers =
      field_numbers(scene.grid, slab_rows(comm, slab), result.pressure, result.displacement);
  nlohmann::json summary =
      common_summary(scene, automatic, report, apply_seconds, options.repeat, numbers);
  add_contact_summary(summary, scene, result, solve_seconds);
  add_rank_summary(summary, comm, scene, *op);
  return {slab,
          std::move(result.pressure),
          std::move(result.displacement),
          std::move(result.gap),
          std::move(summary),
          result.converged ? RunStatus::ok : RunStatus::not_converged};
}

}  // namespace

DistributedSceneRun compute_distributed_scene(const Communicator& comm,
                                              const PreparedScene& prepared,
                                              const SceneRunOptions& options) {
  ProgressObserver silent;
  ProgressObserver& progress = options.progress ? *options.progress : silent;
  return prepared.scene.contact
             ? compute_contact(comm, prepared.scene, prepared.automatic, options, progress)
             : compute_pressure(comm, prepared.scene, prepared.automatic, options, progress);
}

}  // namespace coatfft::scene
