#include "cli/scene.hpp"

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "cli/csv.hpp"
#include "cli/input_file.hpp"
#include "cli/npy.hpp"
#include "core/detail/parse_name.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "materials/catalog.hpp"

namespace coatfft::cli {

namespace {

// Reads the keys of one TOML table, remembering which were used so that unknown keys (typos)
// are refused instead of silently ignored.
class SectionReader {
 public:
  SectionReader(const toml::table& table, std::string name)
      : table_(table), name_(std::move(name)) {}

  bool has(std::string_view key) const { return table_.contains(key); }

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
  /// The enumerator named by the string at `key` (`fallback` when absent), by `parse` (which
  /// throws InvalidArgument "\"x\" is not one of ..." for an unknown name).
  template <typename Enum, typename Parse>
  Enum named(std::string_view key, Enum fallback, Parse&& parse) {
    if (!has(key)) return fallback;
    const std::string value = string(key);
    try {
      return parse(value);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(detail::concat(where(key), " = ", e.what()));
    }
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
    COATFFT_REQUIRE(node != nullptr, "[", name_, "] missing required key \"", key, "\"");
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
  const double E = reader.number("E");
  const double nu = reader.number("nu");
  return Material(E, nu);
}

Grid read_grid(const toml::table& root) {
  SectionReader reader(section(root, "grid", true), "grid");
  return in_section("grid", [&] {
    const auto nx = reader.integer("nx");
    const auto ny = reader.integer("ny");
    // Guard against input that would exhaust memory before FFTW does (2nx x 2ny padded arrays).
    COATFFT_REQUIRE(nx <= 65536 && ny <= 65536, "nx = ", nx, ", ny = ", ny,
                    ": at most 65536 cells per direction");
    Grid grid(nx, ny, reader.number("lx"), reader.number("ly"));
    reader.finish();
    return grid;
  });
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
    COATFFT_REQUIRE(spec.amplitude > 0, reader.where(amplitude_key), " = ", spec.amplitude,
                    " Pa must be > 0");
    spec.radius = reader.number("a");
    const double half_domain = 0.5 * std::min(grid.lx(), grid.ly());
    COATFFT_REQUIRE(spec.radius > 0 && spec.radius <= half_domain, reader.where("a"), " = ",
                    spec.radius, " m must be > 0 and at most half the domain (", half_domain,
                    " m)");
    spec.sampling = reader.choice("sampling", "centre", {"centre", "cell_average"}) == "centre"
                        ? Sampling::centre
                        : Sampling::cell_average;
  }
  reader.finish();
  return spec;
}

double positive(SectionReader& reader, std::string_view key) {
  const double value = reader.number(key);
  COATFFT_REQUIRE(value > 0, reader.where(key), " = ", value, " must be > 0");
  return value;
}

Field read_height_map(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  COATFFT_REQUIRE(ext == ".npy" || ext == ".csv", "[contact] path = ", file.string(),
                  ": must end in .npy or .csv");
  return ext == ".npy" ? read_npy(file) : read_csv_matrix(file);
}

ContactSpec read_contact(const toml::table& table, const Grid& grid, const LayerStack& body,
                         const std::filesystem::path& scene_dir) {
  SectionReader reader(table, "contact");
  ContactSpec spec;
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
    spec.indenter = HeightMap{read_height_map(file)};
    const Field& h = std::get<HeightMap>(spec.indenter).heights;
    COATFFT_REQUIRE(h.rows() == grid.nx() && h.cols() == grid.ny(), file.string(), ": shape (",
                    h.cols(), ", ", h.rows(), ") but the grid needs (ny, nx) = (", grid.ny(), ", ",
                    grid.nx(), ")");
    for (Eigen::Index j = 0; j < h.cols(); ++j)
      for (Eigen::Index i = 0; i < h.rows(); ++i)
        COATFFT_REQUIRE(std::isfinite(h(i, j)), file.string(), ": row ", j, ", column ", i,
                        ": height ", h(i, j), " is not finite");
  }
  COATFFT_REQUIRE(reader.has("load") != reader.has("approach"),
                  "[contact] give exactly one of load (N) and approach (m)");
  if (reader.has("load")) spec.load = positive(reader, "load");
  if (reader.has("approach")) spec.approach = positive(reader, "approach");
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
  if (reader.has("indenter_material") || reader.has("indenter_E") || reader.has("indenter_nu")) {
    COATFFT_REQUIRE(body.is_homogeneous(),
                    "[contact] an elastic indenter needs a homogeneous body (composite modulus); "
                    "for a coated body the indenter must be rigid");
    if (reader.has("indenter_material")) {
      spec.indenter_material = material_by_name(reader.string("indenter_material"));
    } else {
      const double E = reader.number("indenter_E");
      const double nu = reader.number("indenter_nu");
      try {
        spec.indenter_material = Material(E, nu);
      } catch (const InvalidArgument& e) {
        throw InvalidArgument(
            detail::concat(reader.where("indenter_E"), ", indenter_nu: ", e.what()));
      }
    }
  }
  // Catch geometry errors (a sphere smaller than the domain) before any work is done.
  in_section("contact", [&] { check_indenter(grid, spec.indenter); });
  reader.finish();
  return spec;
}

// Keys that would be ignored by the chosen method are refused: a user who sets alpha for dcfft
// believes it does something.
void refuse_keys_not_applying(const SectionReader& reader, Method method) {
  const bool pipeline = method == Method::frf_spectral || method == Method::frf_dcfft;
  for (const char* key : {"alpha", "g0", "g0_tol"})
    COATFFT_REQUIRE(pipeline || !reader.has(key), reader.where(key),
                    ": applies only to the FRF "
                    "pipelines \"frf-spectral\" and \"frf-dcfft\", not to name = \"",
                    to_string(method), "\"");
  for (const char* key : {"planning", "wisdom"})
    COATFFT_REQUIRE(method != Method::direct || !reader.has(key), reader.where(key),
                    ": FFTW settings do not apply to name = \"direct\", which uses no FFT");
}

MethodSpec read_method(const toml::table& root, const std::filesystem::path& scene_dir) {
  SectionReader reader(section(root, "method", false), "method");
  MethodSpec spec;
  OperatorOptions& o = spec.options;
  o.method = reader.named("name", o.method, parse_method);
  refuse_keys_not_applying(reader, o.method);
  o.alpha = reader.number("alpha", o.alpha);
  // omitted is not a user's choice: a load-controlled contact makes it (report_approach).
  o.g0 = reader.named("g0", o.g0, [](std::string_view name) {
    return detail::parse_name(name, std::array{G0Method::regularized, G0Method::quadrature});
  });
  o.g0_tolerance = reader.number("g0_tol", o.g0_tolerance);
  o.planning = reader.named("planning", o.planning, parse_planning);
  const auto threads = reader.integer("threads", o.threads);
  COATFFT_REQUIRE(threads >= 1 && threads <= max_threads, reader.where("threads"), " = ", threads,
                  " must be in 1..", max_threads);
  o.threads = static_cast<int>(threads);
  if (reader.has("wisdom")) {
    spec.wisdom = reader.string("wisdom");
    if (spec.wisdom.is_relative()) spec.wisdom = scene_dir / spec.wisdom;
  }
  reader.finish();
  return spec;
}

constexpr std::ptrdiff_t max_direct_cells = 1 << 16;

// A scene is a few hundred bytes; a megabyte is far beyond any real one.
constexpr std::uintmax_t max_scene_bytes = 1 << 20;

toml::table parse_scene_text(const std::string& text, const std::filesystem::path& path) {
  try {
    toml::table root = toml::parse(text, path.string());
    const std::set<std::string> known{"grid",     "substrate", "coating",
                                      "pressure", "contact",   "method"};
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

Scene read_scene(const std::filesystem::path& path) {
  // read_input_file's messages start with the path already.
  const std::string text = read_input_file(path, "a scene file", max_scene_bytes);
  return with_file_name(path, [&] {
    const toml::table root = parse_scene_text(text, path);
    const std::filesystem::path scene_dir = path.parent_path();
    Scene scene{read_grid(root), read_body(root),
                std::nullopt,    read_method(root, scene_dir),
                std::nullopt,    {}};
    in_section("method", [&] { check_operator_options(scene.grid, scene.method.options); });
    // Direct summation costs (nx ny)^2 operations per application: hours beyond this size.
    COATFFT_REQUIRE(
        scene.method.options.method != Method::direct || scene.grid.nb_cells() <= max_direct_cells,
        "[method] name = \"direct\" on ", scene.grid.nx(), " x ", scene.grid.ny(),
        " cells: direct summation is limited to ", max_direct_cells,
        " cells (its cost grows as (nx ny)^2); use \"dcfft\", which gives the same "
        "result");
    COATFFT_REQUIRE(root.contains("pressure") != root.contains("contact"),
                    "a scene needs exactly one of [pressure] (known load) and [contact]");
    if (root.contains("pressure"))
      scene.pressure = read_pressure(section(root, "pressure", true), scene.grid, scene_dir);
    else
      scene.contact = in_section("contact", [&] {
        return read_contact(section(root, "contact", true), scene.grid, scene.body, scene_dir);
      });
    // g(0) only shifts every displacement by one constant, which a load-controlled contact
    // absorbs in its approach; when that approach is not reported, g(0) is not computed at all.
    if (scene.contact && !scene.contact->report_approach)
      scene.method.options.g0 = G0Method::omitted;
    scene.input_files.push_back(path);
    if (scene.pressure && scene.pressure->kind == PressureKind::file)
      scene.input_files.push_back(scene.pressure->file);
    if (scene.contact && !scene.contact->height_file.empty())
      scene.input_files.push_back(scene.contact->height_file);
    return scene;
  });
}

LayerStack read_scene_body(const std::filesystem::path& path) {
  const std::string text = read_input_file(path, "a scene file", max_scene_bytes);
  return with_file_name(path, [&] { return read_body(parse_scene_text(text, path)); });
}

}  // namespace coatfft::cli
