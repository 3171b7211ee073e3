#include "scene/detail/scene_loads.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "core/error.hpp"
#include "io/grid_file.hpp"
#include "loads/load_limits.hpp"
#include "materials/catalog.hpp"
#include "scene/detail/section_reader.hpp"
#include "surfaces/detrend.hpp"

namespace coatfft::scene {

AnalyticLoad analytic_load(const PressureSpec& spec) {
  return {spec.kind == PressureKind::hertz ? AnalyticLoad::Kind::hertz
                                           : AnalyticLoad::Kind::uniform_disk,
          spec.amplitude, spec.radius, spec.sampling};
}

AxisymmetricLoad axisymmetric_shape(const PressureSpec& spec) {
  return spec.kind == PressureKind::hertz ? AxisymmetricLoad::hertz
                                          : AxisymmetricLoad::uniform_disk;
}

PressureSpec read_pressure(const toml::table& table, const Grid& grid,
                           const std::filesystem::path& scene_dir) {
  SectionReader reader(table, "pressure");
  PressureSpec spec;
  const std::string kind = reader.choice("kind", "", {"hertz", "uniform_disk", "file"});
  spec.kind = kind == "hertz"          ? PressureKind::hertz
              : kind == "uniform_disk" ? PressureKind::uniform_disk
                                       : PressureKind::file;
  if (spec.kind == PressureKind::file) {
    spec.file = reader.string("path");
    if (spec.file.is_relative()) spec.file = scene_dir / spec.file;
  } else {
    const char* amplitude_key = spec.kind == PressureKind::hertz ? "p0" : "p";
    spec.amplitude = reader.number(amplitude_key);
    spec.radius = reader.number("a");
    spec.sampling = reader.choice("sampling", "centre", {"centre", "cell_average"}) == "centre"
                        ? Sampling::centre
                        : Sampling::cell_average;
    // The cells are checked on the scene's final grid (scene_pressure): `grid` may be only the
    // domain of a refinement.
    require_disk_load(grid, spec.amplitude, spec.radius, Sampling::cell_average,
                      {reader.where(amplitude_key), reader.where("a"), "[grid]"});
  }
  reader.finish();
  return spec;
}

namespace {

// [contact] topography = "FILE" (read by read_scene_topography): a measured surface's heights z
// (peaks up, towards a rigid flat), `detrend` "none" (default: the file as it is), "mean" or
// "plane" (its tilt on the instrument), pressed by a rigid flat: the gap max(z) - z
// (surfaces/detrend.hpp), as a height map; `unit` and `missing` as the file was read.
void read_topography(SectionReader& reader, const SceneContext& context, ContactSpec& spec) {
  COATFFT_REQUIRE(!reader.has("indenter"), reader.where("topography"),
                  " is pressed by a rigid flat: give it or an indenter, not both");
  reader.string("topography");
  reader.string("unit", "");
  reader.string("missing", "");
  const Detrend detrend = detrend_from_name(
      reader.choice("detrend", "none", {"none", "mean", "plane"}), reader.where("detrend"));
  spec.indenter_name = "topography";
  spec.height_file = context.topography->file;
  TopographyGap t =
      topography_gap(*context.topography, context.grid, detrend, context.periodic, context.pad);
  spec.topography_pad = context.pad;
  spec.indenter = HeightMap{std::move(t.gap)};
  spec.topography = std::move(t.report);
}

// [contact] indenter and its keys: the shape, checked against the grid (a height map's shape and
// values; a cylinder's length, a punch's radius within the domain).
void read_indenter(SectionReader& reader, const SceneContext& context, ContactSpec& spec) {
  if (context.topography) return read_topography(reader, context, spec);
  for (const char* key : {"detrend", "unit", "missing"})
    COATFFT_REQUIRE(!reader.has(key), reader.where(key),
                    " applies to a measured topography ([contact] topography = \"FILE\")");
  const Grid& grid = context.grid;
  const std::filesystem::path& scene_dir = context.scene_dir;
  spec.indenter_name = reader.choice(
      "indenter", "", {"sphere", "paraboloid", "cylinder", "flat_punch", "height_map"});
  const std::string& kind = spec.indenter_name;
  const double half_domain = 0.5 * std::min(grid.lx(), grid.ly());
  if (kind == "sphere") {
    spec.indenter = Sphere{positive(reader, "radius")};
  } else if (kind == "paraboloid") {
    spec.indenter = Paraboloid{positive(reader, "radius")};
  } else if (kind == "cylinder") {
    spec.indenter = Cylinder{positive(reader, "radius"), reader.number("length", 0.0),
                             positive(reader, "end_radius")};
    const double length = std::get<Cylinder>(spec.indenter).flat_length;
    COATFFT_REQUIRE(length >= 0 && length < grid.lx(), reader.where("length"), " = ", length,
                    " m must be >= 0 and shorter than the domain (lx = ", grid.lx(), " m)");
  } else if (kind == "flat_punch") {
    spec.indenter = FlatPunch{positive(reader, "radius"), positive(reader, "edge_radius")};
    const double a = std::get<FlatPunch>(spec.indenter).radius;
    COATFFT_REQUIRE(a < half_domain, reader.where("radius"), " = ", a,
                    " m: the punch must fit in the domain (radius < ", half_domain, " m)");
  } else {
    std::filesystem::path file = reader.string("path");
    if (file.is_relative()) file = scene_dir / file;
    spec.height_file = file;
    spec.indenter = HeightMap{};
    if (context.height_map_values)
      spec.indenter = HeightMap{io::read_grid_file(file, grid, "[contact] path", "height")};
    else
      io::check_grid_npy(file, grid, "[contact] path",
                         "a height map");  // spec.indenter: an empty HeightMap
  }
}

// [contact] load or approach: one value, or a list (a sweep, its values solved in ascending
// order on one operator: ContactSolver::solve_sweep); the smallest value for a list. With
// adhesion a value may be zero or negative (the bodies apart, or a tensile load).
double control_value(SectionReader& reader, const char* key, ContactSpec& spec, bool adhesive) {
  if (!reader.is_array(key)) return adhesive ? reader.number(key) : positive(reader, key);
  std::vector<double> values = reader.numbers(key);
  COATFFT_REQUIRE(!values.empty() && values.size() <= max_sweep_values, reader.where(key),
                  " lists ", values.size(), " values: a sweep takes 1 to ", max_sweep_values);
  for (const double v : values)
    COATFFT_REQUIRE(adhesive || v > 0, reader.where(key), " holds ", v,
                    ": every value must be > 0 (zero or negative only with adhesion)");
  std::sort(values.begin(), values.end());
  spec.sweep = values;
  return values.front();
}

// [contact] load or approach, and the solver's keys (tolerance, max_iterations, friction).
void read_contact_control(SectionReader& reader, ContactSpec& spec) {
  COATFFT_REQUIRE(reader.has("load") != reader.has("approach"),
                  "[contact] give exactly one of load (N) and approach (m)",
                  reader.misspelling({"load", "approach"}));
  const bool adhesive = reader.has("adhesion");
  if (reader.has("load")) spec.load = control_value(reader, "load", spec, adhesive);
  if (reader.has("approach")) spec.approach = control_value(reader, "approach", spec, adhesive);
  spec.report_approach = reader.boolean("report_approach", spec.report_approach);
  COATFFT_REQUIRE(spec.report_approach || spec.load, reader.where("report_approach"),
                  " = false: under approach control the approach is the input and is always "
                  "reported; report_approach = false needs load control (load = ...)");
  spec.tolerance = reader.number("tolerance", spec.tolerance);
  COATFFT_REQUIRE(spec.tolerance > 0 && spec.tolerance < 1, reader.where("tolerance"), " = ",
                  spec.tolerance, " must be in (0, 1)");
  const auto max_iterations = reader.integer("max_iterations", spec.max_iterations);
  COATFFT_REQUIRE(max_iterations >= 1 && max_iterations <= 1000000, reader.where("max_iterations"),
                  " = ", max_iterations, " must be in 1..1000000");
  spec.max_iterations = static_cast<int>(max_iterations);
  spec.friction = reader.number("friction", 0.0);
  COATFFT_REQUIRE(spec.friction >= 0.0 && spec.friction <= 10.0, reader.where("friction"), " = ",
                  spec.friction, " must be in [0, 10]");
}

// [contact] tangential_load [N] or tangential_shift [m]: one value, or a path (a list) kept in
// the order given -- friction depends on the history, so unlike a sweep it is not sorted. Under
// load control |Q| < mu P is checked here; under approach control, where P is solved for, after
// the normal solve.
void read_tangential(SectionReader& reader, ContactSpec& spec) {
  const bool by_load = reader.has("tangential_load"), by_shift = reader.has("tangential_shift");
  if (!by_load && !by_shift) return;
  COATFFT_REQUIRE(!(by_load && by_shift),
                  "[contact] give one of tangential_load (N) and tangential_shift (m), not both");
  const char* key = by_load ? "tangential_load" : "tangential_shift";
  spec.tangential_control = by_load ? TangentialControl::load : TangentialControl::shift;
  spec.tangential_path = reader.is_array(key);
  spec.tangential =
      spec.tangential_path ? reader.numbers(key) : std::vector<double>{reader.number(key)};
  COATFFT_REQUIRE(!spec.tangential.empty() && spec.tangential.size() <= max_path_steps,
                  reader.where(key), " lists ", spec.tangential.size(),
                  " values: a tangential path takes 1 to ", max_path_steps);
  COATFFT_REQUIRE(spec.friction > 0.0, reader.where(key),
                  " needs friction: [contact] friction = mu > 0 (Coulomb's law, |q| <= mu p)");
  COATFFT_REQUIRE(spec.sweep.empty(), reader.where(key),
                  " takes one normal load or approach, not a sweep (a list)");
  if (!by_load || !spec.load) return;
  const double limit = spec.friction * *spec.load;
  for (const double q : spec.tangential)
    COATFFT_REQUIRE(std::abs(q) < limit, reader.where(key), " = ", q,
                    " N reaches full sliding: |Q| must stay below friction x load = ", limit,
                    " N (full sliding is [contact] friction without a tangential load)");
}

// [contact] hardness [Pa] and unload: the capped pressure (docs/scene_format.md). The load the
// whole domain carries at the hardness bounds every load; unload runs a sweep's values back.
void read_hardness(SectionReader& reader, const Grid& grid, ContactSpec& spec) {
  if (reader.has("hardness")) {
    const double hardness = reader.number("hardness");
    COATFFT_REQUIRE(std::isfinite(hardness) && hardness > 0, reader.where("hardness"), " = ",
                    hardness, " Pa must be finite and > 0");
    spec.hardness = hardness;
    COATFFT_REQUIRE(spec.friction == 0.0, reader.where("hardness"),
                    " is not combined with friction yet: the capped contact is frictionless "
                    "(no tangential_load, tangential_shift or friction)");
    const double capacity = hardness * grid.lx() * grid.ly();
    if (spec.load) {
      const double largest = spec.sweep.empty() ? *spec.load : spec.sweep.back();
      COATFFT_REQUIRE(largest < capacity, reader.where("load"), " = ", largest,
                      " N: under hardness = ", hardness,
                      " Pa no load reaches the whole domain at the hardness, ", capacity, " N");
    }
  }
}

// [contact] adhesion = "dugdale", work_of_adhesion [J/m^2], adhesion_range [m].
void read_adhesion(SectionReader& reader, ContactSpec& spec) {
  if (!reader.has("adhesion")) {
    for (const char* key : {"work_of_adhesion", "adhesion_range"})
      COATFFT_REQUIRE(!reader.has(key), reader.where(key), " needs adhesion = \"dugdale\"");
    return;
  }
  reader.choice("adhesion", "dugdale", {"dugdale"});
  AdhesionOptions law;
  for (auto [key, value] :
       {std::pair{"work_of_adhesion", &law.work_of_adhesion}, {"adhesion_range", &law.range}}) {
    *value = reader.number(key);
    COATFFT_REQUIRE(std::isfinite(*value) && *value > 0, reader.where(key), " = ", *value,
                    " must be finite and > 0");
  }
  COATFFT_REQUIRE(!spec.hardness, reader.where("adhesion"),
                  " is not combined with hardness yet: give one of the two");
  COATFFT_REQUIRE(spec.friction == 0.0, reader.where("adhesion"),
                  " is not combined with friction yet: the adhesive contact is frictionless");
  spec.adhesion = law;
}

// [contact] unload: a sweep of a hysteretic contact (hardness or adhesion) runs back down.
void read_unload(SectionReader& reader, ContactSpec& spec) {
  spec.unload = reader.boolean("unload", false);
  if (!spec.unload) return;
  COATFFT_REQUIRE(!spec.sweep.empty(), reader.where("unload"),
                  " = true needs a list of loads or approaches (the values to load through "
                  "and unload back)");
  COATFFT_REQUIRE(spec.hardness || spec.adhesion, reader.where("unload"),
                  " = true needs hardness or adhesion: the unloading of an elastic contact "
                  "repeats its loading");
}

// [contact] indenter_material, or indenter_E and indenter_nu: an elastic indenter, through the
// composite modulus of a homogeneous body.
void read_elastic_indenter(SectionReader& reader, const LayerStack* stack_body, ContactSpec& spec) {
  if (!reader.has("indenter_material") && !reader.has("indenter_E") && !reader.has("indenter_nu"))
    return;
  COATFFT_REQUIRE(stack_body != nullptr,
                  "[contact] an elastic indenter needs a homogeneous body given by [substrate] "
                  "(composite modulus); with a table body ([frf]) the indenter must be rigid");
  COATFFT_REQUIRE(stack_body->is_homogeneous(),
                  "[contact] an elastic indenter needs a homogeneous body (composite modulus); "
                  "for a coated body the indenter must be rigid");
  if (reader.has("indenter_material"))
    spec.indenter_material = material_by_name(reader.string("indenter_material"));
  else
    spec.indenter_material = material_from_moduli(reader, "indenter_E", "indenter_nu");
}

}  // namespace

ContactSpec read_contact(const toml::table& table, const SceneContext& context,
                         const LayerStack* stack_body) {
  SectionReader reader(table, "contact");
  ContactSpec spec;
  const Grid& grid = context.grid;
  read_indenter(reader, context, spec);
  read_contact_control(reader, spec);
  read_tangential(reader, spec);
  read_hardness(reader, grid, spec);
  read_adhesion(reader, spec);
  read_unload(reader, spec);
  read_elastic_indenter(reader, stack_body, spec);
  // Catch geometry errors (a sphere smaller than the domain) before any work is done; a height
  // map whose values were not read was checked as far as its header goes.
  if (context.height_map_values || !std::holds_alternative<HeightMap>(spec.indenter))
    in_section("contact", [&] { check_indenter(grid, spec.indenter); });
  reader.finish();
  return spec;
}

std::vector<double> ContactSpec::solved_values() const {
  return sweep_order(sweep, unload);
}

ShearSpec read_shear(const toml::table& root, const std::filesystem::path& scene_dir) {
  SectionReader reader(section(root, "shear", true), "shear");
  ShearSpec spec;
  spec.proportional = reader.choice("kind", "", {"proportional", "file"}) == "proportional";
  if (spec.proportional) {
    spec.friction = reader.number("mu");
    COATFFT_REQUIRE(spec.friction >= 0.0 && spec.friction <= 10.0, reader.where("mu"), " = ",
                    spec.friction, " must be in [0, 10]");
    spec.along_x = reader.choice("direction", "x", {"x", "y"}) == "x";
  } else {
    for (auto [key, path] : {std::pair{"path_x", &spec.path_x}, {"path_y", &spec.path_y}})
      if (reader.has(key)) {
        *path = reader.string(key);
        if (path->is_relative()) *path = scene_dir / *path;
      }
    COATFFT_REQUIRE(!spec.path_x.empty() || !spec.path_y.empty(),
                    "[shear] kind = \"file\" needs path_x, path_y or both");
  }
  reader.finish();
  return spec;
}

}  // namespace coatfft::scene
