#include "scene/detail/scene_output.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/input_file.hpp"
#include "scene/detail/section_reader.hpp"
#include "stress/stress_kernel.hpp"
#include "stress/stress_operator.hpp"

namespace coatfft::scene {

namespace {

// The names of [output] fields and the flag each sets; "summary" sets none, since summary.json
// is always written (naming it is allowed, so that a list can say everything it expects).
struct OutputField {
  std::string_view name;
  bool OutputSpec::*flag;
};
constexpr std::array<OutputField, 18> output_fields{
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
     {"von_mises_interfaces", &OutputSpec::von_mises_interfaces},
     {"shear", &OutputSpec::shear},
     {"stick", &OutputSpec::stick},
     {"slip", &OutputSpec::slip},
     {"plastic", &OutputSpec::plastic},
     {"residual_gap", &OutputSpec::residual_gap},
     {"ux", &OutputSpec::ux},
     {"uy", &OutputSpec::uy}}};

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

// The kernels' cost, estimated before any work (stress/stress_kernel.hpp).
void check_stress_kernel_cost(const Scene& scene, const StressSpec& spec,
                              const std::vector<double>& planes) {
  StressKernelOptions kernel;
  kernel.alpha = spec.alpha;
  if (!planes.empty()) {
    const double z = *std::min_element(planes.begin(), planes.end());
    const double n = spec.boundary == Boundary::periodic
                         ? periodic_stress_evaluations(scene.grid, planes, kernel)
                         : stress_kernel_evaluations(scene.grid, planes, kernel);
    COATFFT_REQUIRE(n <= kernel.max_evaluations, "[stress] the plane at z = ", z,
                    " m is too shallow for a ", scene.grid.lx(), " x ", scene.grid.ly(),
                    " m domain: its kernel needs about ", n, " FRF evaluations (limit ",
                    kernel.max_evaluations, "; the cost grows like (L/z)^2)");
  }
}

}  // namespace

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
    spec.uz = spec.pressure = spec.displacement_csv = spec.ux = spec.uy = false;
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
  spec.boundary = scene.boundary;
  COATFFT_REQUIRE(!scene.periodic() || !reader.has("alpha"), reader.where("alpha"),
                  " sets the sampling lattice of a free surface's kernels; with [grid] boundary = "
                  "\"periodic\" they lie on the period's own lattice: remove it");
  const std::int64_t alpha = reader.integer("alpha", 16);
  COATFFT_REQUIRE(alpha >= 2 && alpha <= 32, reader.where("alpha"), " = ", alpha,
                  " must be an integer in [2, 32]");
  COATFFT_REQUIRE(scene.periodic() || alpha * std::max(scene.grid.nx(), scene.grid.ny()) <= 16384,
                  reader.where("alpha"), " = ", alpha, " times ",
                  std::max(scene.grid.nx(), scene.grid.ny()),
                  " cells exceeds the 16384-point sampling lattice; lower alpha");
  spec.alpha = static_cast<int>(alpha);
  const std::vector<double> planes = stress_planes(spec, *scene.body).depths;
  check_stress_kernel_cost(scene, spec, planes);
  COATFFT_REQUIRE(!spec.depths.empty() || spec.section,
                  "[stress] give depths = [...] or section = \"xz\" (or both)");
  const std::size_t asked = spec.depths.size() + std::size_t(spec.nz);
  COATFFT_REQUIRE(planes.size() <= StressOperator::max_planes, "[stress] asks for ", asked,
                  " planes (and ", planes.size() - asked,
                  " on the interfaces' two sides); at most ", StressOperator::max_planes);
  reader.finish();
  return spec;
}

}  // namespace coatfft::scene
