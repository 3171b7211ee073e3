#pragma once
// The scene file: a small TOML description of one computation (docs/scene_format.md).
// read_scene() validates everything it can before any work starts, so that a bad scene ends with
// one line naming the key and the value, and no output.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "contact/adhesive_contact.hpp"
#include "contact/indenter.hpp"
#include "contact/partial_slip.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/grid.hpp"
#include "frf/frf.hpp"
#include "frf/layer_modes.hpp"
#include "layers/layer_stack.hpp"
#include "loads/sampling.hpp"
#include "model/grid_refinement.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft::scene {

/// [pressure] kind.
enum class PressureKind { hertz, uniform_disk, file };

/// [pressure]: a known surface pressure.
struct PressureSpec {
  PressureKind kind = PressureKind::hertz;
  double amplitude = 0;                  ///< p0 (hertz) or p (uniform_disk) [Pa]
  double radius = 0;                     ///< a [m]
  Sampling sampling = Sampling::centre;  ///< kind = "sampling": "centre" or "cell_average"
  std::filesystem::path file;            ///< .npy or .csv of shape (ny, nx) [Pa], for kind = "file"
};

/// The analytic load of a hertz or uniform_disk [pressure] (not a file): for the estimate of its
/// discretisation error and the grid chosen for it (loads/), and its shape for the Hankel
/// reference and the reduced models (validation/, model/).
AnalyticLoad analytic_load(const PressureSpec& spec);
AxisymmetricLoad axisymmetric_shape(const PressureSpec& spec);

/// [method]: how displacements are computed. The keys name, alpha, g0, g0_tol, planning and
/// threads are read into the library's OperatorOptions (checked by check_operator_options). A
/// load-controlled contact with report_approach = false sets options.g0 = G0Method::omitted.
struct MethodSpec {
  /// name = "auto" (the default): method, kernel tolerance, threads and a reduced body are
  /// chosen for `tolerance` (scene/automatic_method.hpp, docs/auto.md); `options` then holds the
  /// user's planning and, in threads, the most threads the choice may use.
  bool automatic = true;
  /// [method] tolerance: the largest operator error relative to max |u| (name = "auto" only).
  double tolerance = 1e-4;
  OperatorOptions options;
  /// Set by resolve_automatic_method when a simpler body is within the tolerance
  /// (model/body_reduction.hpp): the body the operator is built for.
  std::optional<LayerStack> reduced_body;
  std::filesystem::path wisdom;  ///< FFTW wisdom file to load and save (optional)
  /// name = "auto" on a periodic boundary, resolved to dcfft or frf-split by the body alone
  /// (automatic is then false): reported as requested "auto". A coating far thinner than a cell
  /// is left out first where its effect is within the tolerance (resolve_automatic_method):
  /// `reduced_body` is then set and `reduction_note` says why, for summary.json's warnings.
  bool auto_periodic = false;
  std::string reduction_note;
  /// Whether [method] planning was given; otherwise read_scene chooses (planning_for_contact).
  bool planning_given = false;
};

/// The fewest cells for which a contact scene without [method] planning plans its operator with
/// FFTW_MEASURE: a contact solve applies the operator about a hundred times, and from 2048^2
/// cells measured plans repay their planning within the solve (docs/benchmarks.md, "Planning").
inline constexpr std::ptrdiff_t contact_measure_cells = 2048 * 2048;

/// The planning rule of an operator applied many times (a contact scene's; every operator Python
/// makes, which are for reuse): FFTW_MEASURE from contact_measure_cells cells unless `method`
/// says its planning.
void plan_for_repeated_use(MethodSpec& method, const Grid& grid);

/// [contact]: a frictionless normal contact with an indenter (contact/).
struct ContactSpec {
  std::string indenter_name;  ///< "sphere", "paraboloid", "cylinder", "flat_punch", "height_map"
  Indenter indenter;
  std::filesystem::path height_file;  ///< the file of a height_map indenter
  std::optional<double> load;         ///< total normal load [N] (load control), or
  std::optional<double> approach;     ///< rigid-body approach [m] (approach control)
  /// load or approach given as a list (a sweep): its values, ascending; load or approach then
  /// holds the smallest. Empty for one value.
  std::vector<double> sweep;
  double tolerance = 1e-10;
  int max_iterations = 1000;
  /// Report the rigid-body approach (load control). false: the approach is not computed, and an
  /// FRF operator is built without g(0) (G0Method::omitted), which load control does not need
  /// (docs/contact.md). Must stay true under approach control.
  bool report_approach = true;
  /// Elastic indenter (homogeneous bodies only): the body's modulus is replaced by the
  /// composite modulus 1/E* = 1/E*_body + 1/E*_indenter (Johnson section 4.2).
  std::optional<Material> indenter_material;
  /// Coefficient of friction of a full sliding along +x: q_x = friction p on the body's surface,
  /// for the stresses ([stress]); the normal contact is solved frictionless (docs/stress.md).
  /// With tangential_load or tangential_shift, the friction of the partial slip.
  double friction = 0.0;
  /// Partial slip (contact/partial_slip.hpp): tangential_load [N] or tangential_shift [m] along
  /// +x, one value or a path (a list, solved in the order given); empty: none.
  std::vector<double> tangential;
  TangentialControl tangential_control = TangentialControl::load;
  /// The tangential values were given as a list (a fretting path): fretting.csv, the partial-slip
  /// fields stacked one per step, summary.json "fretting".
  bool tangential_path = false;
  bool partial_slip() const { return !tangential.empty(); }
  /// Full sliding: friction without a tangential load or shift (q_x = friction p).
  bool full_sliding() const { return friction > 0.0 && tangential.empty(); }
  /// [contact] hardness [Pa]: the pressure capped at H, the overlap of the cells at H plastic
  /// depth (ContactOptions::hardness; docs/contact.md, "Hardness"). Unset: elastic.
  std::optional<double> hardness;
  /// [contact] adhesion = "dugdale" with work_of_adhesion [J/m^2] and adhesion_range [m]
  /// (contact/adhesive_contact.hpp; docs/contact.md, "Adhesion"): approaches may then be zero or
  /// negative and loads negative. Unset: no attraction.
  std::optional<AdhesionOptions> adhesion;
  /// [contact] unload = true (a sweep with hardness or adhesion): after the ascending values the
  /// values below the largest, descending, each from the previous state
  /// (ContactSolver::solve_sweep, solve_adhesive_path).
  bool unload = false;
  /// The values of a sweep in the order they are solved: ascending, then with unload the
  /// unloading branch. Empty for one value.
  std::vector<double> solved_values() const;
  /// The number of a sweep's values on its loading branch (the rest unload).
  std::size_t loading_steps() const { return sweep.size(); }
  /// A measured topography's report for summary.json (scene/scene_topography.hpp); null for
  /// an indenter.
  nlohmann::json topography;
  /// [grid] pad: cells of out-of-reach gap around the topography on each side.
  std::int64_t topography_pad = 0;
};

/// [output]: the files `coatfft run` writes (docs/scene_format.md, "[output]"). summary.json is
/// always written; it is not a choice. Without [output] (or its key fields) every file that
/// applies is written.
struct OutputSpec {
  bool uz = true;                ///< uz.npy
  bool pressure = true;          ///< pressure.npy
  bool gap = false;              ///< gap.npy: a [contact] scene only (its default there is true)
  bool displacement_csv = true;  ///< displacement.csv
  /// stress.npy, von_mises.npy: by default those of [stress] depths
  bool stress = false;
  bool von_mises = false;
  /// stress_section.npy, von_mises_section.npy: by default those of [stress] section
  bool stress_section = false;
  bool von_mises_section = false;
  /// stress_interfaces.npy, von_mises_interfaces.npy: each interface's planes from both sides;
  /// by default those of [stress] on a coated body
  bool stress_interfaces = false;
  bool von_mises_interfaces = false;
  /// The in-plane surface response is computed: [shear] or [contact] friction (they need it), or
  /// [stress] with ux.npy or uy.npy wanted, on a bonded body (not an [frf] table) whose traction
  /// kernels are affordable (convolution/kernels/traction_kernels.hpp)
  bool in_plane = false;
  /// ux.npy, uy.npy, written where in_plane is computed: by default both
  bool ux = true;
  bool uy = true;
  /// format = "netcdf": the .npy files' arrays are written instead as the variables of one
  /// NetCDF file, fields.nc (scene/scene_netcdf.hpp); summary.json and the CSV files stay.
  bool netcdf = false;
  /// [output] fields was given: only the files it names are written.
  bool listed = false;
  /// sweep.csv, and uz.npy, pressure.npy, gap.npy stacked one per value: a [contact] sweep
  bool sweep = false;
  /// A partial slip ([contact] tangential_load or tangential_shift): shear_x.npy and shear_y.npy
  /// (the tractions), stick.npy (uint8), slip_x.npy and slip_y.npy (the last step's slip); for a
  /// path each stacked one per step, and fretting.csv.
  bool shear = false;
  bool stick = false;
  bool slip = false;
  bool fretting = false;
  /// Under [contact] hardness: plastic.npy, the plastic depth [m] (stacked one per value for a
  /// sweep), and with unload residual_gap.npy, the gap the permanent surface leaves at zero load.
  bool plastic = false;
  bool residual_gap = false;
};

/// [shear]: known tangential tractions that the surface receives, with a [pressure]: q = friction
/// p along one axis (kind = "proportional"), or read from files (kind = "file"). They enter the
/// stresses ([stress]); the surface displacements uz do not include them yet.
struct ShearSpec {
  bool proportional = true;      ///< kind = "proportional"; false: kind = "file"
  double friction = 0.0;         ///< mu [-] of kind = "proportional"
  bool along_x = true;           ///< direction = "x" (true) or "y"
  std::filesystem::path path_x;  ///< kind = "file": q_x [Pa], .npy or .csv (ny, nx); may be empty
  std::filesystem::path path_y;  ///< the same for q_y
};

/// [stress]: the stresses inside the body on planes z = const and on the section y = 0
/// (docs/stress.md; stress/stress_operator.hpp), under the scene's pressure.
struct StressSpec {
  std::vector<double> depths;                 ///< depths [m] of the planes, each > 0
  InterfaceSide side = InterfaceSide::below;  ///< at_interface: the medium of an interface depth
                                              ///< (LayerStack::locate)
  bool section = false;                       ///< section = "xz": the plane y = 0
  double depth_max = 0.0;                     ///< the section's deepest row [m]
  int nz = 0;                                 ///< the section's rows, at depth_max k/nz, k = 1..nz
  int alpha = 16;  ///< period of the kernels' sampling lattice over the domain (docs/stress.md)
  Boundary boundary = Boundary::free;  ///< [grid] boundary: periodic, the kernels on the period's
                                       ///< lattice
};

/// The most values of a [contact] sweep (a guard against runaway input: each is a solve and a
/// field of each output).
inline constexpr std::size_t max_sweep_values = 256;
/// The most steps a tangential path ([contact] tangential_load or tangential_shift as a list)
/// takes.
inline constexpr std::size_t max_path_steps = 10000;

/// The most cells along an axis that [grid] refine = "auto" chooses.
inline constexpr std::ptrdiff_t max_refined_cells = 1024;

/// [grid] refine = "auto": nx and ny chosen so that the load's discretisation error stays within
/// tolerance_total less the operator's tolerance (model/grid_refinement.hpp).
struct GridRefinement {
  double tolerance_total = 0.0;
  GridChoice choice;
};

/// Exactly one of `pressure` and `contact` is set. The body is `frf` when [frf] gives a table
/// (every operator is built from it; `body`, if [substrate] is also given, only describes what
/// the table claims to be, for `coatfft validate-frf`); otherwise `body`, which is then set.
struct Scene {
  Grid grid;
  std::optional<LayerStack> body;
  std::optional<PressureSpec> pressure;
  MethodSpec method;
  std::optional<ContactSpec> contact;
  /// The scene file and the files it names (pressure, height map, FRF table): the run's inputs,
  /// which no output may replace. The wisdom file is method.wisdom.
  std::vector<std::filesystem::path> input_files;
  OutputSpec output;
  std::shared_ptr<const Frf> frf = nullptr;  ///< [frf]: the body as a table (TabulatedFrf)
  std::filesystem::path frf_file = {};       ///< [frf] path
  std::optional<GridRefinement> refinement = std::nullopt;  ///< set when [grid] refine = "auto"
  std::optional<StressSpec> stress = std::nullopt;          ///< [stress]
  std::optional<ShearSpec> shear = std::nullopt;            ///< [shear]
  /// [grid] boundary: "periodic", the surface repeats over the domain (docs/scene_format.md).
  Boundary boundary = Boundary::free;
  bool periodic() const { return boundary == Boundary::periodic; }
};

/// Every plane a [stress] scene computes, with the medium of each on an interface.
struct StressPlanes {
  std::vector<double> depths;
  std::vector<InterfaceSide> sides;
};

/// The planes of `spec` in `body`: the depths, then the section's rows (both in the medium
/// spec.side names where on an interface), then each interface of the body seen from above and
/// from below (its largest shear stress, and the maxima of the media on both of its sides).
StressPlanes stress_planes(const StressSpec& spec, const LayerStack& body);

/// The FRF of the scene's body: the [frf] table, or make_frf of [substrate] and [[coating]].
std::shared_ptr<const Frf> body_frf(const Scene& scene);

/// The body of a [contact] scene's normal compliance: with an elastic indenter, the half-space of
/// the composite modulus replaces the (homogeneous) body (Johnson 1985, section 4.2); otherwise
/// the scene is left as it is.
void use_normal_compliance_body(Scene& scene);

/// Parses and validates a scene file. Throws InvalidArgument with a one-line message
/// ("scene.toml: [grid] nx = 0: ...") on any problem. Relative file paths in the scene are
/// taken relative to the scene file's folder.
/// How read_scene reads the files a scene names.
struct SceneReading {
  /// false: a height_map indenter's file is checked as far as its header (a .npy of the grid's
  /// shape) and its values are left unread (an empty HeightMap): a distributed run reads its rows
  /// on each rank (io/npy_slab.hpp).
  bool height_map_values = true;
  /// The memory the run may use [bytes] (--max-memory; by default what the machine has): what is
  /// allocated while the scene is read (a measured topography, its padded gap) is checked against
  /// it first. The whole scene's estimate is check_memory's (scene/resources.hpp), after reading.
  std::optional<double> max_memory{};
};

Scene read_scene(const std::filesystem::path& path, const SceneReading& reading = {});

/// Parses only the body of a scene ([substrate] and [[coating]]), for commands that need no
/// grid or load (`coatfft frf`). Other sections must still be known ones.
LayerStack read_scene_body(const std::filesystem::path& path);

}  // namespace coatfft::scene
