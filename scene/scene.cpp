#include "scene/scene.hpp"

#include <toml++/toml.h>

#include <set>
#include <string>

#include "convolution/kernels/periodic_traction_kernels.hpp"
#include "convolution/kernels/traction_kernels.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "io/input_file.hpp"
#include "scene/detail/scene_body.hpp"
#include "scene/detail/scene_grid.hpp"
#include "scene/detail/scene_loads.hpp"
#include "scene/detail/scene_method.hpp"
#include "scene/detail/scene_output.hpp"
#include "scene/detail/section_reader.hpp"
#include "scene/method_request.hpp"
#include "scene/resources.hpp"
#include "scene/scene_topography.hpp"
#include "validation/hertz_contact.hpp"

namespace coatfft::scene {

namespace {

// A [contact] sweep solves the normal contact at each value and writes its fields stacked, one
// per value, with sweep.csv; the stresses and friction take one load so far, and displacement.csv
// (x, y, uz lines) holds one field.
void check_sweep(Scene& scene) {
  COATFFT_REQUIRE(!scene.stress,
                  "[stress] takes one load: a [contact] sweep (a list of loads or "
                  "approaches) solves the normal contact only so far");
  COATFFT_REQUIRE(scene.contact->friction == 0.0,
                  "[contact] friction takes one load: a sweep (a list of loads or approaches) "
                  "solves the frictionless contact only so far");
  OutputSpec& output = scene.output;
  COATFFT_REQUIRE(!(output.listed && output.displacement_csv),
                  "[output] fields: \"displacement_csv\" holds one field: a [contact] sweep writes "
                  "uz.npy, pressure.npy and gap.npy stacked, one per value, and sweep.csv");
  output.displacement_csv = false;
  output.sweep = true;
}

// The traction kernels' cost (free or periodic surface), estimated before any work.
double traction_evaluations(const Scene& scene) {
  return scene.periodic() ? periodic_traction_kernel_evaluations(scene.grid, *scene.body)
                          : traction_kernel_evaluations(scene.grid, *scene.body);
}

bool traction_kernels_affordable(const Scene& scene) {
  return traction_evaluations(scene) <= LatticeOptions{}.max_evaluations;
}

// Tangential tractions act on the surface displacements of any bonded layer stack
// (convolution/kernels/traction_kernels.hpp) and on the stresses. An [frf] table gives no
// tangential response, and on a body with a frictionless interface a net tangential force has no
// equilibrium (the coating slides; docs/theory.md 2.3). The layered kernels' cost is checked before
// any work.
void check_tangential(const Scene& scene, const char* key) {
  COATFFT_REQUIRE(!scene.frf && scene.body, key,
                  " needs a body of [substrate] and [[coating]]: an [frf] table gives no "
                  "response to tangential tractions");
  for (std::size_t i = 0; i < scene.body->coatings().size(); ++i)
    COATFFT_REQUIRE(scene.body->coatings()[i].interface_below != Interface::frictionless, key,
                    ": tangential tractions on a body with a frictionless interface (below "
                    "coating ",
                    i + 1, ") are not supported: a net tangential force has no equilibrium there");
  COATFFT_REQUIRE(traction_kernels_affordable(scene), key, ": the top coating (",
                  detail::brief(scene.body->coatings().front().thickness),
                  " m) is so thin against the ", detail::brief(scene.grid.lx()), " x ",
                  detail::brief(scene.grid.ly()), " m domain that its traction kernels need about ",
                  detail::brief(traction_evaluations(scene)), " FRF evaluations (limit ",
                  detail::brief(LatticeOptions{}.max_evaluations),
                  "; the cost grows like (L/h)^2)");
}

// A partial slip writes its tractions, stick zone and slip (for a path one per step, stacked, with
// fretting.csv), by default all of them; an [output] fields list names those it wants, and only a
// partial slip has them.
void check_partial_slip_outputs(Scene& scene) {
  OutputSpec& output = scene.output;
  const bool partial_slip = scene.contact && scene.contact->partial_slip();
  if (!output.listed) output.shear = output.stick = output.slip = partial_slip;
  for (const auto& [wanted, name] :
       {std::pair{output.shear, "shear"}, {output.stick, "stick"}, {output.slip, "slip"}})
    COATFFT_REQUIRE(!wanted || partial_slip, "[output] fields: \"", name,
                    "\" needs a partial slip: [contact] tangential_load or tangential_shift");
  output.fretting = partial_slip && scene.contact->tangential_path;
}

// A capped contact writes its plastic depth, and an unloading sweep its residual gap, by
// default; an [output] fields list names those it wants, and only such a contact has them.
void check_plastic_outputs(Scene& scene) {
  OutputSpec& output = scene.output;
  const bool capped = scene.contact && scene.contact->hardness;
  const bool unloads = capped && scene.contact->unload;
  if (!output.listed) {
    output.plastic = capped;
    output.residual_gap = unloads;
  }
  COATFFT_REQUIRE(!output.plastic || capped,
                  "[output] fields: \"plastic\" needs a capped contact: [contact] hardness");
  COATFFT_REQUIRE(!output.residual_gap || unloads,
                  "[output] fields: \"residual_gap\" needs an unloading sweep: [contact] "
                  "hardness, a list of loads or approaches and unload = true");
}

// The in-plane surface displacements (ux.npy, uy.npy), with tangential tractions or stresses, of
// a bonded body whose traction kernels are affordable (checked before when tractions act): on a
// periodic surface its periodic kernels. Tractions need the response (their normal displacement
// enters uz, or the contact); stresses alone only for the files, so a list without them skips it.
void check_in_plane_outputs(Scene& scene) {
  OutputSpec& output = scene.output;
  const bool tractions = scene.shear || (scene.contact && scene.contact->friction > 0.0);
  const bool possible = (scene.stress || tractions) && !scene.frf && scene.body &&
                        scene.body->all_bonded() && traction_kernels_affordable(scene);
  for (const auto& [wanted, name] : {std::pair{output.ux, "ux"}, {output.uy, "uy"}})
    COATFFT_REQUIRE(!output.listed || !wanted || possible, "[output] fields: \"", name,
                    "\" needs the in-plane surface response: [stress], [shear] or [contact] "
                    "friction on a bonded body (docs/scene_format.md, \"[output]\")");
  output.in_plane = possible && (tractions || output.ux || output.uy);
}

// [shear], with a known [pressure]; its files are inputs of the run.
void read_shear_loads(const toml::table& root, const std::filesystem::path& scene_dir,
                      Scene& scene) {
  COATFFT_REQUIRE(scene.pressure.has_value(),
                  "[shear] goes with a known [pressure]; a "
                  "[contact] scene gives its friction as [contact] friction = mu");
  scene.shear = read_shear(root, scene_dir);
  check_tangential(scene, "[shear]");
  for (const auto& file : {scene.shear->path_x, scene.shear->path_y})
    if (!file.empty()) scene.input_files.push_back(file);
}

// The scene file and the files it names, after [shear]'s: the run's inputs (Scene::input_files).
void add_input_files(const std::filesystem::path& path, Scene& scene) {
  scene.input_files.push_back(path);
  if (scene.frf) scene.input_files.push_back(scene.frf_file);
  if (scene.pressure && scene.pressure->kind == PressureKind::file)
    scene.input_files.push_back(scene.pressure->file);
  if (scene.contact && !scene.contact->height_file.empty())
    scene.input_files.push_back(scene.contact->height_file);
}

// A scene is a few hundred bytes; a megabyte is far beyond any real one.
constexpr std::uintmax_t max_scene_bytes = 1 << 20;

toml::table parse_scene_text(const std::string& text, const std::filesystem::path& path) {
  try {
    toml::table root = toml::parse(text, path.string());
    const std::set<std::string> known{"grid",   "substrate", "coating", "pressure", "contact",
                                      "method", "output",    "frf",     "stress",   "shear"};
    for (auto&& [key, node] : root) {
      COATFFT_REQUIRE(known.count(std::string(key.str())), "unknown section or key \"",
                      detail::shorten(key.str()), "\"");
    }
    return root;
  } catch (const toml::parse_error& e) {
    throw InvalidArgument(detail::concat(
        "line ", e.source().begin.line, ": TOML syntax error: ", detail::shorten(e.description())));
  }
}

// Scene errors start with the file name, so that a message stands on its own.
template <typename Parse>
auto with_file_name(const std::filesystem::path& path, Parse&& parse) {
  try {
    return parse();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat(path.string(), ": ", e.what()));
  }
}

}  // namespace

Scene read_scene(const std::filesystem::path& path, const SceneReading& reading) {
  // read_input_file's messages start with the path already.
  const std::string text = io::read_input_file(path, "a scene file", max_scene_bytes);
  return with_file_name(path, [&] {
    const toml::table root = parse_scene_text(text, path);
    const std::filesystem::path scene_dir = path.parent_path();
    const std::optional<SceneTopography> topography =
        read_scene_topography(root, scene_dir, reading.max_memory);
    const GridSection grid = read_grid(root, topography ? &*topography : nullptr);
    Scene scene{grid.grid.value_or(Grid(1, 1, grid.lx, grid.ly)),
                read_optional_body(root),
                std::nullopt,
                read_method(root, scene_dir, grid.boundary),
                std::nullopt,
                {},
                {}};
    scene.boundary = grid.boundary;
    if (root.contains("frf")) read_frf(root, scene_dir, scene);
    resolve_periodic_method(scene.method, scene.body && !scene.frf ? &*scene.body : nullptr);
    if (grid.tolerance_total) scene.grid = refine_grid(root, grid, scene);
    in_section("method", [&] { check_operator_options(scene.grid, scene.method.options); });
    COATFFT_REQUIRE(root.contains("pressure") != root.contains("contact"),
                    "a scene needs exactly one of [pressure] (known load) and [contact]");
    if (root.contains("pressure"))
      scene.pressure = read_pressure(section(root, "pressure", true), scene.grid, scene_dir);
    else if (topography && grid.pad > 0)  // before the padded gap is allocated
      check_pad_memory(scene, topography->map.heights, grid.pad, reading.max_memory);
    if (root.contains("contact"))
      scene.contact = in_section("contact", [&] {
        const SceneContext context{scene.grid, scene.periodic(),
                                   scene_dir,  topography ? &*topography : nullptr,
                                   grid.pad,   reading.height_map_values};
        return read_contact(section(root, "contact", true), context,
                            scene.frf ? nullptr : &*scene.body);
      });
    if (scene.contact) plan_for_repeated_use(scene.method, scene.grid);
    scene.output = read_output(root, scene.contact.has_value());
    if (root.contains("stress")) scene.stress = read_stress(root, scene);
    check_stress_outputs(scene.output, scene.stress.value_or(StressSpec{}),
                         scene.stress && !scene.body->interface_depths().empty());
    if (root.contains("shear")) read_shear_loads(root, scene_dir, scene);
    if (scene.contact && scene.contact->friction > 0.0)
      check_tangential(scene, !scene.contact->partial_slip() ? "[contact] friction"
                              : scene.contact->tangential_control == TangentialControl::load
                                  ? "[contact] tangential_load"
                                  : "[contact] tangential_shift");
    check_partial_slip_outputs(scene);
    if (scene.contact && !scene.contact->sweep.empty()) check_sweep(scene);
    check_plastic_outputs(scene);
    check_in_plane_outputs(scene);
    // g(0) only shifts every displacement by one constant, which a load-controlled contact
    // absorbs in its approach; when that approach is not reported, g(0) is not computed at all.
    if (scene.contact && !scene.contact->report_approach)
      scene.method.options.g0 = G0Method::omitted;
    add_input_files(path, scene);
    return scene;
  });
}

LayerStack read_scene_body(const std::filesystem::path& path) {
  const std::string text = io::read_input_file(path, "a scene file", max_scene_bytes);
  return with_file_name(path, [&] { return read_body(parse_scene_text(text, path)); });
}

StressPlanes stress_planes(const StressSpec& spec, const LayerStack& body) {
  StressPlanes planes{spec.depths, {}};
  for (int k = 1; k <= spec.nz; ++k) planes.depths.push_back(spec.depth_max * k / spec.nz);
  planes.sides.assign(planes.depths.size(), spec.side);
  // The interfaces' own depths, which LayerStack::locate places on them exactly.
  for (const double z : body.interface_depths())
    for (const InterfaceSide side : {InterfaceSide::above, InterfaceSide::below}) {
      planes.depths.push_back(z);
      planes.sides.push_back(side);
    }
  return planes;
}

std::shared_ptr<const Frf> body_frf(const Scene& scene) {
  if (scene.frf) return scene.frf;
  return make_frf(*scene.body);
}

void use_normal_compliance_body(Scene& scene) {
  if (!scene.contact || !scene.contact->indenter_material) return;
  // Two homogeneous elastic bodies in frictionless normal contact deform as one half-space of
  // the composite modulus; only E* enters the normal compliance.
  const Material& body = scene.body->substrate();
  const double E_star = composite_modulus(body, *scene.contact->indenter_material);
  const double nu = body.poisson_ratio();
  scene.body = LayerStack(Material(E_star * (1 - nu * nu), nu));
}

}  // namespace coatfft::scene
