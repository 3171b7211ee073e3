#include "scene/scene.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <thread>
#include <vector>

#include "convolution/kernels/periodic_traction_kernels.hpp"
#include "convolution/kernels/traction_kernels.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "io/grid_file.hpp"
#include "io/input_file.hpp"
#include "loads/load_limits.hpp"
#include "materials/catalog.hpp"
#include "scene/frf_table_file.hpp"
#include "scene/key_spelling.hpp"
#include "scene/method_request.hpp"
#include "scene/resources.hpp"
#include "scene/scene_topography.hpp"
#include "stress/stress_kernel.hpp"
#include "stress/stress_operator.hpp"
#include "surfaces/detrend.hpp"
#include "validation/hertz_contact.hpp"

namespace coatfft::scene {

namespace {

// Reads the keys of one TOML table, remembering which were used so that unknown keys (typos)
// are refused instead of silently ignored.
class SectionReader {
 public:
  SectionReader(const toml::table& table, std::string name)
      : table_(table), name_(std::move(name)) {}

  bool has(std::string_view key) const { return table_.contains(key); }
  bool is_array(std::string_view key) const {
    const toml::node* node = table_.get(key);
    return node != nullptr && node->is_array();
  }

  double number(std::string_view key) {
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is_number(), where(key), " must be a number, got ", describe(node));
    // An integer too large for an exact double (9007199254740993) is still a number: rounded.
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    COATFFT_REQUIRE(std::isfinite(value), where(key), " = ", value, " must be finite");
    return value;
  }
  double number(std::string_view key, double fallback) { return has(key) ? number(key) : fallback; }

  std::int64_t integer(std::string_view key) {
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is_integer(), where(key), " must be an integer, got ", describe(node));
    return node.value<std::int64_t>().value();
  }
  std::int64_t integer(std::string_view key, std::int64_t fallback) {
    return has(key) ? integer(key) : fallback;
  }

  bool boolean(std::string_view key, bool fallback) {
    if (!has(key)) return fallback;
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is_boolean(), where(key), " must be true or false, got ", describe(node));
    return node.value<bool>().value();
  }

  std::string string(std::string_view key) {
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is_string(), where(key), " must be a string, got ", describe(node));
    return node.value<std::string>().value();
  }
  std::string string(std::string_view key, std::string fallback) {
    return has(key) ? string(key) : fallback;
  }
  /// The list of finite numbers at `key` (possibly empty).
  std::vector<double> numbers(std::string_view key) {
    const toml::node& node = require(key);
    const toml::array* array = node.as_array();
    COATFFT_REQUIRE(array != nullptr, where(key), " must be a list of numbers, got ",
                    describe(node));
    std::vector<double> values;
    for (const toml::node& e : *array) {
      COATFFT_REQUIRE(e.is_number(), where(key),
                      " must be a list of numbers, got an entry of type ", describe(e));
      const double v = e.is_integer() ? static_cast<double>(e.as_integer()->get())
                                      : e.as_floating_point()->get();
      COATFFT_REQUIRE(std::isfinite(v), where(key), " holds ", v, ": every entry must be finite");
      values.push_back(v);
    }
    return values;
  }
  /// The list of strings at `key` (possibly empty).
  std::vector<std::string> strings(std::string_view key) {
    const toml::node& node = require(key);
    const toml::array* array = node.as_array();
    COATFFT_REQUIRE(array != nullptr, where(key), " must be a list of strings, got ",
                    describe(node));
    std::vector<std::string> values;
    for (const toml::node& element : *array) {
      COATFFT_REQUIRE(element.is_string(), where(key),
                      " must be a list of strings, got an entry of type ", describe(element));
      values.push_back(element.value<std::string>().value());
    }
    return values;
  }
  std::string choice(std::string_view key, std::string fallback,
                     std::initializer_list<std::string_view> allowed) {
    std::string value = string(key, std::move(fallback));
    std::string list;
    for (auto a : allowed) {
      if (a == value) return value;
      list += (list.empty() ? "\"" : ", \"") + std::string(a) + "\"";
    }
    throw InvalidArgument(
        detail::concat(where(key), " = \"", detail::shorten(value), "\" is not one of ", list));
  }

  /// A key of the section that nothing read and that looks like a misspelling of one of
  /// `expected` (scene/key_spelling.hpp), for a refusal that a missing key causes; "" if none.
  std::string misspelling(const std::vector<std::string_view>& expected) const {
    std::vector<std::string> unread;
    for (auto&& [key, node] : table_)
      if (!used_.count(std::string(key.str()))) unread.emplace_back(key.str());
    return misspelling_hint(unread, expected);
  }

  /// Refuses every key that was not read.
  void finish() const {
    for (auto&& [key, node] : table_) {
      COATFFT_REQUIRE(used_.count(std::string(key.str())), "[", name_, "] unknown key \"",
                      detail::shorten(key.str()), "\"", line_of(node));
    }
  }

  std::string where(std::string_view key) const {
    std::string line;
    if (const toml::node* node = table_.get(key)) line = line_of(*node);
    return detail::concat("[", name_, "] ", key, line);
  }

 private:
  const toml::node& require(std::string_view key) {
    const toml::node* node = table_.get(key);
    COATFFT_REQUIRE(node != nullptr, "[", name_, "] missing required key \"", key, "\"",
                    misspelling({key}));
    used_.insert(std::string(key));
    return *node;
  }
  static std::string line_of(const toml::node& node) {
    return node.source().begin ? detail::concat(" (line ", node.source().begin.line, ")") : "";
  }
  static std::string describe(const toml::node& node) {
    std::ostringstream os;
    os << node.type();
    return os.str();
  }

  const toml::table& table_;
  std::string name_;
  std::set<std::string> used_;
};

const toml::table& section(const toml::table& root, std::string_view name, bool required) {
  static const toml::table empty;
  const toml::node* node = root.get(name);
  COATFFT_REQUIRE(node != nullptr || !required, "missing required section [", name, "]");
  if (node == nullptr) return empty;
  COATFFT_REQUIRE(node->is_table(), "[", name, "] must be a table");
  return *node->as_table();
}

// Library constructors validate values; prefix their messages with the section they came from.
template <typename Build>
auto in_section(std::string_view name, Build&& build) {
  try {
    return build();
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    if (message.rfind("[", 0) == 0) throw;
    throw InvalidArgument(detail::concat("[", name, "] ", message));
  }
}

// Material(E, nu) from the keys `e_key` and `nu_key`: the library's limits, named by those keys.
Material material_from_moduli(SectionReader& reader, const char* e_key, const char* nu_key) {
  const double E = reader.number(e_key);
  const double nu = reader.number(nu_key);
  try {
    return Material(E, nu);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat(reader.where(e_key), ", ", nu_key, ": ", e.what()));
  }
}

Material read_material(SectionReader& reader) {
  if (reader.has("material")) {
    COATFFT_REQUIRE(!reader.has("E") && !reader.has("nu"), reader.where("material"),
                    ": give either material or E and nu, not both");
    const std::string name = reader.string("material");
    try {
      return material_by_name(name);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(detail::concat(reader.where("material"), ": ", e.what()));
    }
  }
  return material_from_moduli(reader, "E", "nu");
}

// What the sections after [grid] read against: the grid, its boundary, the scene's folder and a
// measured topography read before the grid (null without one).
struct SceneContext {
  const Grid& grid;
  bool periodic = false;
  const std::filesystem::path& scene_dir;
  const SceneTopography* topography = nullptr;
  std::int64_t pad = 0;           ///< [grid] pad of the topography
  bool height_map_values = true;  ///< SceneReading::height_map_values
};

// [grid]: nx and ny, or refine = "auto" with tolerance_total (the grid is then chosen once the
// load and the body are known: refine_grid).
struct GridSection {
  double lx = 0.0;
  double ly = 0.0;
  std::optional<Grid> grid;               // nx and ny given
  std::optional<double> tolerance_total;  // refine = "auto"
  bool periodic = false;                  // boundary = "periodic"
  std::int64_t pad = 0;                   // a topography's pad [cells each side]
};

// [contact] topography = "FILE" with its unit and missing keys, read before the grid (whose keys
// the file may give); the keys are read again, and checked with the others, by read_contact.
std::optional<SceneTopography> read_scene_topography(const toml::table& root,
                                                     const std::filesystem::path& scene_dir,
                                                     std::optional<double> max_memory) {
  if (!root.contains("contact")) return std::nullopt;
  SectionReader reader(section(root, "contact", true), "contact");
  if (!reader.has("topography")) return std::nullopt;
  return in_section("contact", [&] {
    // The keys' own mistakes first, before the file is read.
    COATFFT_REQUIRE(!reader.has("indenter"), reader.where("topography"),
                    " is pressed by a rigid flat: give it or an indenter, not both");
    detrend_from_name(reader.choice("detrend", "none", {"none", "mean", "plane"}),
                      reader.where("detrend"));
    SceneTopography t;
    t.file = reader.string("topography");
    if (t.file.is_relative()) t.file = scene_dir / t.file;
    topography::ReadOptions options;
    options.unit = reader.string("unit", "");
    options.missing = topography::missing_points_from_name(
        reader.choice("missing", "refuse", {"refuse", "fill"}), reader.where("missing"));
    options.max_memory = max_memory;
    t.map = topography::read_topography(t.file, options);
    return t;
  });
}

// [grid] on a measured topography: the section and its nx, ny, lx, ly are optional (the file's
// unless given, checked against it), the boundary the file's periodic flag unless given.
GridSection read_topography_grid(SectionReader& reader, const SceneTopography& t) {
  COATFFT_REQUIRE(!reader.has("refine"), reader.where("refine"),
                  ": a measured topography's grid is its own (nx, ny of the file)");
  const auto integer = [&](const char* key) {
    return reader.has(key) ? std::optional(reader.integer(key)) : std::nullopt;
  };
  const auto number = [&](const char* key) {
    return reader.has(key) ? std::optional(reader.number(key)) : std::nullopt;
  };
  const TopographyGrid keys =
      topography_grid_keys(t, integer("nx"), integer("ny"), number("lx"), number("ly"));
  const char* file_boundary = t.map.periodic.value_or(false) ? "periodic" : "free";
  GridSection g{keys.lx, keys.ly, std::nullopt, std::nullopt, false, reader.integer("pad", 0)};
  g.periodic = reader.choice("boundary", file_boundary, {"free", "periodic"}) == "periodic";
  COATFFT_REQUIRE(!g.periodic || (keys.nx % 2 == 0 && keys.ny % 2 == 0),
                  "boundary = \"periodic\" needs even nx and ny: the topography has nx = ", keys.nx,
                  ", ny = ", keys.ny, " (boundary = \"free\" takes any)");
  // The map and `pad` cells of out-of-reach gap on each side, at the map's spacing.
  const std::int64_t nx = keys.nx + 2 * g.pad, ny = keys.ny + 2 * g.pad;
  COATFFT_REQUIRE(g.pad >= 0 && nx <= Grid::max_cells_per_axis && ny <= Grid::max_cells_per_axis,
                  reader.where("pad"), " = ", g.pad, " must be >= 0, with at most ",
                  Grid::max_cells_per_axis, " cells per direction in all");
  g.lx = keys.lx * static_cast<double>(nx) / static_cast<double>(keys.nx);
  g.ly = keys.ly * static_cast<double>(ny) / static_cast<double>(keys.ny);
  g.grid = Grid(nx, ny, g.lx, g.ly);
  reader.finish();
  return g;
}

GridSection read_grid(const toml::table& root, const SceneTopography* topography) {
  SectionReader reader(section(root, "grid", topography == nullptr), "grid");
  if (topography)
    return in_section("grid", [&] { return read_topography_grid(reader, *topography); });
  COATFFT_REQUIRE(!reader.has("pad"), reader.where("pad"),
                  " applies to a measured topography ([contact] topography = \"FILE\")");
  return in_section("grid", [&] {
    GridSection g{reader.number("lx"), reader.number("ly"), std::nullopt, std::nullopt, false};
    g.periodic = reader.choice("boundary", "free", {"free", "periodic"}) == "periodic";
    if (reader.choice("refine", "none", {"none", "auto"}) == "auto") {
      COATFFT_REQUIRE(!g.periodic,
                      "refine = \"auto\" chooses grids for free boundaries: give nx "
                      "and ny with boundary = \"periodic\"");
      COATFFT_REQUIRE(!reader.has("nx") && !reader.has("ny"),
                      "refine = \"auto\" chooses nx and ny: remove them");
      const double t = reader.number("tolerance_total");
      COATFFT_REQUIRE(t > 0 && t <= 0.1, reader.where("tolerance_total"), " = ", t,
                      " must be in (0, 0.1]");
      g.tolerance_total = t;
      Grid(1, 1, g.lx, g.ly);  // checks lx and ly now
    } else {
      COATFFT_REQUIRE(!reader.has("tolerance_total"), reader.where("tolerance_total"),
                      ": applies only with refine = \"auto\"");
      const auto nx = reader.integer("nx");
      const auto ny = reader.integer("ny");
      // Grid's own limit (core/grid.hpp), said with the scene's keys.
      COATFFT_REQUIRE(nx <= Grid::max_cells_per_axis && ny <= Grid::max_cells_per_axis, "nx = ", nx,
                      ", ny = ", ny, ": at most ", Grid::max_cells_per_axis,
                      " cells per direction");
      COATFFT_REQUIRE(!g.periodic || (nx % 2 == 0 && ny % 2 == 0),
                      "boundary = \"periodic\" needs "
                      "even nx and ny (nx = ",
                      nx, ", ny = ", ny, ")");
      g.grid = Grid(nx, ny, g.lx, g.ly);
    }
    reader.finish();
    return g;
  });
}

PressureSpec read_pressure(const toml::table& table, const Grid& grid,
                           const std::filesystem::path& scene_dir);

}  // namespace

AnalyticLoad analytic_load(const PressureSpec& spec) {
  return {spec.kind == PressureKind::hertz ? AnalyticLoad::Kind::hertz
                                           : AnalyticLoad::Kind::uniform_disk,
          spec.amplitude, spec.radius, spec.sampling};
}

AxisymmetricLoad axisymmetric_shape(const PressureSpec& spec) {
  return spec.kind == PressureKind::hertz ? AxisymmetricLoad::hertz
                                          : AxisymmetricLoad::uniform_disk;
}

namespace {

// refine = "auto": the grid on which the load's discretisation error is within tolerance_total
// less the operator's tolerance ([method] tolerance, by default a tenth of tolerance_total).
Grid refine_grid(const toml::table& root, const GridSection& g, Scene& scene) {
  MethodSpec& m = scene.method;
  COATFFT_REQUIRE(m.automatic,
                  "[grid] refine = \"auto\" needs [method] name = \"auto\": the "
                  "total tolerance is shared between the load's cells and the operator");
  COATFFT_REQUIRE(root.contains("pressure"),
                  "[grid] refine = \"auto\" applies to a known "
                  "pressure ([pressure] kind = \"hertz\" or \"uniform_disk\")");
  const toml::table& method = section(root, "method", false);
  if (!method.contains("tolerance")) m.tolerance = *g.tolerance_total / 10;
  COATFFT_REQUIRE(m.tolerance < *g.tolerance_total, "[method] tolerance = ", m.tolerance,
                  " must be below [grid] tolerance_total = ", *g.tolerance_total);
  const PressureSpec p = in_section("pressure", [&] {
    return read_pressure(section(root, "pressure", true), Grid(1, 1, g.lx, g.ly), {});
  });
  COATFFT_REQUIRE(p.kind != PressureKind::file,
                  "[grid] refine = \"auto\" needs an analytic "
                  "load: [pressure] kind = \"hertz\" or \"uniform_disk\"");
  const AnalyticLoad load = analytic_load(p);
  GridRefinementOptions options;
  try {
    options.body_factor = load_error_body_factor(*body_frf(scene), load);
  } catch (const InvalidArgument&) {
    throw;
  } catch (const Error& e) {  // the factor's Hankel reference did not converge
    throw InvalidArgument(
        detail::concat("[grid] refine = \"auto\": the load's error on this "
                       "body cannot be estimated (",
                       e.what(), "); give nx and ny"));
  }
  // The search estimates on the grids it tries: at most 1024 cells a side keeps it to seconds
  // and a few hundred MB before the scene's memory is checked. Finer grids: give nx and ny.
  options.max_cells = max_refined_cells;
  const double share = m.tolerance / *g.tolerance_total;
  GridChoice choice = in_section("grid", [&] {
    return choose_grid_for_tolerance(g.lx, g.ly, load, *g.tolerance_total, share, options);
  });
  scene.refinement = GridRefinement{*g.tolerance_total, choice};
  return choice.grid;
}

LayerStack read_body(const toml::table& root) {
  SectionReader substrate_reader(section(root, "substrate", true), "substrate");
  const Material substrate =
      in_section("substrate", [&] { return read_material(substrate_reader); });
  substrate_reader.finish();

  std::vector<Coating> coatings;
  if (const toml::node* node = root.get("coating")) {
    const toml::array* array = node->as_array();
    COATFFT_REQUIRE(array != nullptr && array->is_array_of_tables(),
                    "coating must be an array of tables: write [[coating]]");
    for (std::size_t n = 0; n < array->size(); ++n) {
      const std::string name = detail::concat("coating ", n + 1);
      SectionReader reader(*array->get(n)->as_table(), name);
      coatings.push_back(in_section(name, [&] {
        Coating coating{read_material(reader), reader.number("thickness"), Interface::bonded};
        const std::string interface =
            reader.choice("interface", "bonded", {"bonded", "frictionless"});
        coating.interface_below =
            interface == "bonded" ? Interface::bonded : Interface::frictionless;
        return coating;
      }));
      reader.finish();
    }
  }
  return in_section("coating", [&] { return LayerStack(std::move(coatings), substrate); });
}

// [substrate] is required, unless [frf] gives the body as a table and no stack is described.
std::optional<LayerStack> read_optional_body(const toml::table& root) {
  if (root.contains("frf") && !root.contains("substrate") && !root.contains("coating"))
    return std::nullopt;
  return read_body(root);
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

double positive(SectionReader& reader, std::string_view key) {
  const double value = reader.number(key);
  COATFFT_REQUIRE(value > 0, reader.where(key), " = ", value, " must be > 0");
  return value;
}

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

// `stack_body`: the body the operator is built from when it is a stack, nullptr for a table.
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
// order on one operator: ContactSolver::solve_sweep); the smallest value for a list.
double control_value(SectionReader& reader, const char* key, ContactSpec& spec) {
  if (!reader.is_array(key)) return positive(reader, key);
  std::vector<double> values = reader.numbers(key);
  COATFFT_REQUIRE(!values.empty() && values.size() <= max_sweep_values, reader.where(key),
                  " lists ", values.size(), " values: a sweep takes 1 to ", max_sweep_values);
  for (const double v : values)
    COATFFT_REQUIRE(v > 0, reader.where(key), " holds ", v, ": every value must be > 0");
  std::sort(values.begin(), values.end());
  spec.sweep = values;
  return values.front();
}

// [contact] load or approach, and the solver's keys (tolerance, max_iterations, friction).
void read_contact_control(SectionReader& reader, ContactSpec& spec) {
  COATFFT_REQUIRE(reader.has("load") != reader.has("approach"),
                  "[contact] give exactly one of load (N) and approach (m)",
                  reader.misspelling({"load", "approach"}));
  if (reader.has("load")) spec.load = control_value(reader, "load", spec);
  if (reader.has("approach")) spec.approach = control_value(reader, "approach", spec);
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

ContactSpec read_contact(const toml::table& table, const SceneContext& context,
                         const LayerStack* stack_body) {
  SectionReader reader(table, "contact");
  ContactSpec spec;
  const Grid& grid = context.grid;
  read_indenter(reader, context, spec);
  read_contact_control(reader, spec);
  read_elastic_indenter(reader, stack_body, spec);
  // Catch geometry errors (a sphere smaller than the domain) before any work is done; a height
  // map whose values were not read was checked as far as its header goes.
  if (context.height_map_values || !std::holds_alternative<HeightMap>(spec.indenter))
    in_section("contact", [&] { check_indenter(grid, spec.indenter); });
  reader.finish();
  return spec;
}

// [method]: its keys into a MethodRequest, checked by method_from_request as Python's keywords are.
MethodSpec read_method(const toml::table& root, const std::filesystem::path& scene_dir,
                       bool periodic) {
  SectionReader reader(section(root, "method", false), "method");
  MethodRequest request;
  request.periodic = periodic;
  request.name = reader.string("name", "auto");
  const auto number = [&](const char* key) -> std::optional<double> {
    return reader.has(key) ? std::optional(reader.number(key)) : std::nullopt;
  };
  const auto text = [&](const char* key) -> std::optional<std::string> {
    return reader.has(key) ? std::optional(reader.string(key)) : std::nullopt;
  };
  request.tolerance = number("tolerance");
  request.alpha = number("alpha");
  request.g0 = text("g0");
  request.g0_tol = number("g0_tol");
  request.planning = text("planning");
  if (reader.has("threads")) request.threads = reader.integer("threads");
  request.wisdom = reader.has("wisdom");
  // omitted is not a scene's choice: the program makes it where the level of the displacement
  // does not matter (a load-controlled contact that does not report its approach).
  COATFFT_REQUIRE(request.g0 != "omitted", reader.where("g0"),
                  " = \"omitted\" is set by the program itself (a load-controlled [contact] with "
                  "report_approach = false); use \"regularized\" or \"quadrature\"");
  MethodSpec spec = method_from_request(
      request, {[&](std::string_view key) { return reader.where(key); }, "name"});
  if (request.wisdom) {
    spec.wisdom = reader.string("wisdom");
    if (spec.wisdom.is_relative()) spec.wisdom = scene_dir / spec.wisdom;
  }
  reader.finish();
  return spec;
}

// The names of [output] fields and the flag each sets; "summary" sets none, since summary.json
// is always written (naming it is allowed, so that a list can say everything it expects).
struct OutputField {
  std::string_view name;
  bool OutputSpec::*flag;
};
constexpr std::array<OutputField, 11> output_fields{
    {{"uz", &OutputSpec::uz},
     {"pressure", &OutputSpec::pressure},
     {"gap", &OutputSpec::gap},
     {"displacement_csv", &OutputSpec::displacement_csv},
     {"summary", nullptr},
     {"stress", &OutputSpec::stress},
     {"von_mises", &OutputSpec::von_mises},
     {"stress_section", &OutputSpec::stress_section},
     {"von_mises_section", &OutputSpec::von_mises_section},
     {"stress_interfaces", &OutputSpec::stress_interfaces},
     {"von_mises_interfaces", &OutputSpec::von_mises_interfaces}}};

// Sets the flag of one name of [output] fields, refusing an unknown name and "gap" for a scene
// that has none.
void select_output(OutputSpec& spec, const std::string& name, const SectionReader& reader,
                   bool contact) {
  const auto field = std::find_if(output_fields.begin(), output_fields.end(),
                                  [&](const OutputField& f) { return f.name == name; });
  if (field == output_fields.end()) {
    std::string list;
    for (const OutputField& f : output_fields)
      list += (list.empty() ? "\"" : ", \"") + std::string(f.name) + "\"";
    throw InvalidArgument(detail::concat(reader.where("fields"), ": ", io::quoted_excerpt(name),
                                         " is not one of ", list));
  }
  COATFFT_REQUIRE(contact || name != "gap", reader.where("fields"),
                  ": \"gap\" applies only to a [contact] scene (a known [pressure] has no gap)");
  if (field->flag != nullptr) spec.*field->flag = true;
}

OutputSpec read_output(const toml::table& root, bool contact) {
  SectionReader reader(section(root, "output", false), "output");
  OutputSpec spec;
  spec.gap = contact;
  const bool netcdf = reader.choice("format", "npy", {"npy", "netcdf"}) == "netcdf";
  if (reader.has("fields")) {
    const std::vector<std::string> names = reader.strings("fields");
    COATFFT_REQUIRE(!names.empty(), reader.where("fields"),
                    " = []: name at least one output (summary.json is always written: "
                    "fields = [\"summary\"] writes only it)");
    spec = OutputSpec{};
    spec.uz = spec.pressure = spec.displacement_csv = false;
    spec.listed = true;
    std::set<std::string> seen;
    for (const std::string& name : names) {
      select_output(spec, name, reader, contact);  // a known name from here on
      COATFFT_REQUIRE(seen.insert(name).second, reader.where("fields"), ": \"", name,
                      "\" is listed twice");
    }
  }
  spec.netcdf = netcdf;
  reader.finish();
  return spec;
}

// The stress files: by default every one [stress] computes; an [output] fields list names those
// it wants, each of something [stress] computes (`spec` is empty without [stress]; `interfaces`:
// [stress] is given, on a body with an interface).
void check_stress_outputs(OutputSpec& output, const StressSpec& spec, bool interfaces) {
  const bool planes = !spec.depths.empty();
  if (!output.listed) {
    output.stress = output.von_mises = planes;
    output.stress_section = output.von_mises_section = spec.section;
    output.stress_interfaces = output.von_mises_interfaces = interfaces;
    return;
  }
  for (const auto& [wanted, name] : {std::pair{output.stress_interfaces, "stress_interfaces"},
                                     {output.von_mises_interfaces, "von_mises_interfaces"}})
    COATFFT_REQUIRE(!wanted || interfaces, "[output] fields: \"", name,
                    "\" needs [stress] on a body with an interface (a [[coating]])");
  for (const auto& [wanted, name] :
       {std::pair{output.stress, "stress"}, {output.von_mises, "von_mises"}})
    COATFFT_REQUIRE(!wanted || planes, "[output] fields: \"", name,
                    "\" needs planes: give [stress] depths");
  for (const auto& [wanted, name] : {std::pair{output.stress_section, "stress_section"},
                                     {output.von_mises_section, "von_mises_section"}})
    COATFFT_REQUIRE(!wanted || spec.section, "[output] fields: \"", name,
                    "\" needs the section: give [stress] section = \"xz\"");
}

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

// [stress]: planes at depth and the section y = 0. The stress kernels need the layers themselves
// (docs/theory.md 2.7), which an [frf] table does not give.
StressSpec read_stress(const toml::table& root, const Scene& scene) {
  SectionReader reader(section(root, "stress", true), "stress");
  COATFFT_REQUIRE(scene.body.has_value() && !scene.frf,
                  "[stress] needs the body's layers, given "
                  "by [substrate] and [[coating]]; an [frf] table does not describe the fields "
                  "at depth");
  StressSpec spec;
  if (reader.has("depths")) spec.depths = reader.numbers("depths");
  for (double z : spec.depths)
    COATFFT_REQUIRE(z > 0.0, reader.where("depths"), " holds ", z,
                    ": every depth must be > 0 [m] (z points into the body; the surface plane "
                    "z = 0 is not computed)");
  spec.side = reader.choice("at_interface", "below", {"below", "above"}) == "below"
                  ? InterfaceSide::below
                  : InterfaceSide::above;
  spec.section = reader.has("section");
  if (spec.section) {
    reader.choice("section", "xz", {"xz"});
    spec.depth_max = reader.number("depth_max");
    COATFFT_REQUIRE(spec.depth_max > 0.0, reader.where("depth_max"), " = ", spec.depth_max,
                    " must be > 0 [m]");
    const std::int64_t nz = reader.integer("nz");
    COATFFT_REQUIRE(nz >= 1 && nz <= std::int64_t(StressOperator::max_planes), reader.where("nz"),
                    " = ", nz, " must be in [1, ", StressOperator::max_planes, "]");
    spec.nz = static_cast<int>(nz);
  }
  // A periodic surface's kernels lie on the period's own lattice: alpha, the free surface's
  // sampling period, would be ignored there, so it is refused.
  spec.periodic = scene.periodic;
  COATFFT_REQUIRE(!spec.periodic || !reader.has("alpha"), reader.where("alpha"),
                  " sets the sampling lattice of a free surface's kernels; with [grid] boundary = "
                  "\"periodic\" they lie on the period's own lattice: remove it");
  const std::int64_t alpha = reader.integer("alpha", 16);
  COATFFT_REQUIRE(alpha >= 2 && alpha <= 32, reader.where("alpha"), " = ", alpha,
                  " must be an integer in [2, 32]");
  COATFFT_REQUIRE(spec.periodic || alpha * std::max(scene.grid.nx(), scene.grid.ny()) <= 16384,
                  reader.where("alpha"), " = ", alpha, " times ",
                  std::max(scene.grid.nx(), scene.grid.ny()),
                  " cells exceeds the 16384-point sampling lattice; lower alpha");
  spec.alpha = static_cast<int>(alpha);
  const std::vector<double> planes = stress_planes(spec, *scene.body).depths;
  {
    // The kernels' cost, estimated before any work (stress/stress_kernel.hpp).
    StressKernelOptions kernel;
    kernel.alpha = spec.alpha;
    if (!planes.empty()) {
      const double z = *std::min_element(planes.begin(), planes.end());
      const double n = spec.periodic ? periodic_stress_evaluations(scene.grid, planes, kernel)
                                     : stress_kernel_evaluations(scene.grid, planes, kernel);
      COATFFT_REQUIRE(n <= kernel.max_evaluations, "[stress] the plane at z = ", z,
                      " m is too shallow for a ", scene.grid.lx(), " x ", scene.grid.ly(),
                      " m domain: its kernel needs about ", n, " FRF evaluations (limit ",
                      kernel.max_evaluations, "; the cost grows like (L/z)^2)");
    }
  }
  COATFFT_REQUIRE(!spec.depths.empty() || spec.section,
                  "[stress] give depths = [...] or section = \"xz\" (or both)");
  const std::size_t asked = spec.depths.size() + std::size_t(spec.nz);
  COATFFT_REQUIRE(planes.size() <= StressOperator::max_planes, "[stress] asks for ", asked,
                  " planes (and ", planes.size() - asked,
                  " on the interfaces' two sides); at most ", StressOperator::max_planes);
  reader.finish();
  return spec;
}

// [shear]: tangential tractions with a known pressure.
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

// The traction kernels' cost (free or periodic surface), estimated before any work.
double traction_evaluations(const Scene& scene) {
  return scene.periodic ? periodic_traction_kernel_evaluations(scene.grid, *scene.body)
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

// [frf]: the body as a table of its FRF. Love's coefficients (direct, dcfft) need a material,
// which a table does not give, so those methods are refused here rather than when building.
void read_frf(const toml::table& root, const std::filesystem::path& scene_dir, Scene& scene) {
  SectionReader reader(section(root, "frf", true), "frf");
  std::filesystem::path file = reader.string("path");
  if (file.is_relative()) file = scene_dir / file;
  std::optional<double> c0, c_inf;
  if (reader.has("c0")) c0 = positive(reader, "c0");
  if (reader.has("c_inf")) c_inf = positive(reader, "c_inf");
  reader.finish();
  const Method method = scene.method.options.method;
  const bool chosen = scene.method.automatic || scene.method.auto_periodic;
  COATFFT_REQUIRE(chosen || !uses_love_coefficients(method), "[method] name = \"",
                  to_string(method),
                  "\" uses Love's coefficients of a homogeneous material, which a table body "
                  "([frf]) does not give; use \"frf-split\", \"frf-dcfft\" or \"frf-spectral\"");
  scene.frf = in_section("frf", [&] { return read_frf_table(file, c0, c_inf); });
  scene.frf_file = file;
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
                read_method(root, scene_dir, grid.periodic),
                std::nullopt,
                {},
                {}};
    scene.periodic = grid.periodic;
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
        const SceneContext context{scene.grid, scene.periodic,
                                   scene_dir,  topography ? &*topography : nullptr,
                                   grid.pad,   reading.height_map_values};
        return read_contact(section(root, "contact", true), context,
                            scene.frf ? nullptr : &*scene.body);
      });
    if (scene.contact && !scene.method.planning_given &&
        scene.grid.nb_cells() >= contact_measure_cells)
      scene.method.options.planning = Planning::measure;
    scene.output = read_output(root, scene.contact.has_value());
    if (root.contains("stress")) scene.stress = read_stress(root, scene);
    check_stress_outputs(scene.output, scene.stress.value_or(StressSpec{}),
                         scene.stress && !scene.body->interface_depths().empty());
    if (root.contains("shear")) {
      COATFFT_REQUIRE(scene.pressure.has_value(),
                      "[shear] goes with a known [pressure]; a "
                      "[contact] scene gives its friction as [contact] friction = mu");
      scene.shear = read_shear(root, scene_dir);
      check_tangential(scene, "[shear]");
      for (const auto& file : {scene.shear->path_x, scene.shear->path_y})
        if (!file.empty()) scene.input_files.push_back(file);
    }
    if (scene.contact && scene.contact->friction > 0.0)
      check_tangential(scene, "[contact] friction");
    if (scene.contact && !scene.contact->sweep.empty()) check_sweep(scene);
    // The in-plane surface displacements (ux.npy, uy.npy), with tangential tractions or stresses,
    // of a bonded body whose traction kernels are affordable (checked above when tractions act):
    // on a periodic surface its periodic kernels.
    scene.output.in_plane =
        (scene.stress || scene.shear || (scene.contact && scene.contact->friction > 0.0)) &&
        !scene.frf && scene.body && scene.body->all_bonded() && traction_kernels_affordable(scene);
    // g(0) only shifts every displacement by one constant, which a load-controlled contact
    // absorbs in its approach; when that approach is not reported, g(0) is not computed at all.
    if (scene.contact && !scene.contact->report_approach)
      scene.method.options.g0 = G0Method::omitted;
    scene.input_files.push_back(path);
    if (scene.frf) scene.input_files.push_back(scene.frf_file);
    if (scene.pressure && scene.pressure->kind == PressureKind::file)
      scene.input_files.push_back(scene.pressure->file);
    if (scene.contact && !scene.contact->height_file.empty())
      scene.input_files.push_back(scene.contact->height_file);
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
