#pragma once
// What `coatfft run` computes for a scene, without writing anything: the fields and the object
// that summary.json gets. `coatfft run` (cli/run_command.hpp) computes through the same functions
// and then writes the result; run_scene() hands it to the caller (the Python module's run_scene).
//
// A run has three steps: prepare_scene() reads and checks the scene (name = "auto" resolved, the
// memory checked), the caller then loads the FFTW wisdom file (the CLI loads it and saves it
// after compute_scene; run_scene only reads it), and compute_scene() builds the operator and
// computes.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/types.hpp"
#include "scene/automatic_method.hpp"
#include "scene/progress_observer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_stress.hpp"

namespace coatfft::scene {

/// What the run reports to the shell besides exceptions.
enum class RunStatus { ok, not_converged };

/// What a run of a scene computes: the fields and summary.json's object.
/// The fields of a [contact] sweep, one per value in the order solved (ascending, then with
/// [contact] unload the unloading branch), each (nx, ny); plastic under [contact] hardness.
struct SweepFields {
  std::vector<Field> pressure, uz, gap, plastic;
};

/// The fields of a partial slip, one per step of its path in the order given (one for a single
/// value), each (nx, ny): the tractions the body's surface receives, the stick zone and the slip.
struct PartialSlipFields {
  std::vector<Field> shear_x, shear_y, slip_x, slip_y;
  std::vector<StickMask> stick;
};

struct SceneRun {
  Grid grid;
  Field pressure;            ///< [Pa], shape (nx, ny): the scene's load or the contact pressure
  Field uz;                  ///< [m], shape (nx, ny)
  std::optional<Field> gap;  ///< contact scenes only [m]
  /// Exactly the object summary.json gets. Its "warnings" are not printed anywhere: printing
  /// them is the caller's job (the CLI prints them on stderr).
  nlohmann::json summary;
  /// ok, or not_converged for a contact that did not converge (summary["warning"] says why).
  RunStatus status = RunStatus::ok;
  std::optional<StressRun> stress = std::nullopt;  ///< [stress] scenes only
  /// The in-plane surface displacements [m] of a [stress] scene on a homogeneous body.
  std::optional<Field> ux = std::nullopt, uy = std::nullopt;
  /// Under [contact] hardness: the plastic depth [m] of the summary's solve (the cells at H
  /// have it; a sweep's accumulated), and after an unloading sweep the residual gap [m]: the
  /// heights plus the permanent depth, less their minimum (the surface at zero load).
  std::optional<Field> plastic = std::nullopt, residual_gap = std::nullopt;
  /// A [contact] sweep: every value's fields (pressure, uz and gap above are the last solve's:
  /// the largest value's, or with unload the last unloading step's), and summary["sweep"] its
  /// rows (sweep_csv).
  std::optional<SweepFields> sweep = std::nullopt;
  /// A partial slip ([contact] tangential_load or tangential_shift): every step's fields
  /// (pressure, uz and gap above are the last step's), summary["partial_slip"] the last step's
  /// numbers and, for a path, summary["fretting"] its rows (fretting_csv) and loops.
  std::optional<PartialSlipFields> partial_slip = std::nullopt;
};

/// sweep.csv of a sweep's rows (summary.json's "sweep"): a header line, then per value load,
/// approach (empty when not reported), area_fraction, max_pressure, mean_gap, iterations,
/// operator_applications, converged (1 or 0), max_penetration, plastic_area (0 without a
/// hardness), phase ("load", or "unload" on an unloading branch), cohesive_area (0 without
/// adhesion), at full precision.
std::string sweep_csv(const nlohmann::json& rows);

/// fretting.csv of a path's rows (summary.json's "fretting" "steps"): a header line, then per step
/// step, tangential_load, tangential_shift, stick_area, slip_area, max_shear, dissipated_energy,
/// iterations, converged (1 or 0), at full precision.
std::string fretting_csv(const nlohmann::json& rows);
/// A sweep's fields (each (nx, ny)) as one C-order array (n_values, ny, nx): the layout of the
/// stacked .npy files and of fields.nc's (sweep, ...) variables.
std::vector<double> stacked_fields(const std::vector<Field>& fields);

struct SceneRunOptions {
  int repeat = 1;  ///< operator applications timed; apply_seconds is their median
  /// Memory the run may use [bytes]; by default what the machine has available.
  std::optional<double> max_memory;
  /// Where the stages and the contact solver's iterations are reported; nothing is reported
  /// without one. The caller owns it.
  ProgressObserver* progress = nullptr;
};

/// A scene read and checked, ready to compute.
struct PreparedScene {
  Scene scene;
  std::optional<AutomaticChoice> automatic;  ///< set when [method] name = "auto"
};

/// Reads the scene file, checks options.repeat, resolves name = "auto" (which chooses the body
/// and the method, and so the memory estimate) and refuses a scene whose estimate exceeds
/// options.max_memory. Throws InvalidArgument with the message `coatfft run` prints.
PreparedScene prepare_scene(const std::filesystem::path& scene_file,
                            const SceneRunOptions& options);

/// Builds the operator and computes (writing no file: the caller settles the FFTW wisdom file): the
/// displacement of a known pressure, or the contact solve, each timed over options.repeat
/// applications. Prints nothing but progress. Throws InvalidArgument on a result that cannot be
/// trusted (overflow, a contact reaching the domain edge).
SceneRun compute_scene(PreparedScene prepared, const SceneRunOptions& options);

/// Everything `coatfft run SCENE` does except writing: prepare_scene, the scene's FFTW wisdom
/// file read if it exists (never written), compute_scene. Writes no file and prints nothing (but
/// progress, when given one); throws InvalidArgument with the message `coatfft run` prints for a
/// bad scene.
SceneRun run_scene(const std::filesystem::path& scene_file, const SceneRunOptions& options = {});

}  // namespace coatfft::scene
