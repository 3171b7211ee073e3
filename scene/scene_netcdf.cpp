#include "scene/scene_netcdf.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/netcdf_writer.hpp"

namespace coatfft::scene {

namespace {
using io::NetcdfAttributes;
using io::NetcdfDataset;
using io::NetcdfDimension;
using io::NetcdfVariable;

io::NetcdfAttributes described(const char* units, const char* long_name) {
  return {{{"units", units}, {"long_name", long_name}}, {}};
}

std::span<const double> values(const Field& f) {
  return {f.data(), static_cast<std::size_t>(f.size())};
}

// A sweep's fields, stacked as its .npy files are (n_values, ny, nx), kept alive by `store`.
std::span<const double> stacked(const std::vector<Field>& fields, std::vector<double>& store) {
  store = stacked_fields(fields);
  return store;
}

// The interfaces' planes from both sides (interface, side, component, x, y) and their von Mises
// stress (interface, side, x, y); side 0 is the medium above the interface, 1 the one below.
void add_interface_stress(io::NetcdfDataset& d, const OutputSpec& spec, const StressRun& s) {
  if (!spec.stress_interfaces && !spec.von_mises_interfaces) return;
  std::vector<double> depths;
  for (const auto& interface : s.summary.at("interfaces"))
    depths.push_back(interface.at("depth").get<double>());
  d.dimensions.push_back(
      {"interface", depths.size(), depths, described("m", "depth of the interface")});
  d.dimensions.push_back({"side", 2, {}, {}});
  if (spec.stress_interfaces)
    d.variables.push_back({"stress_interfaces",
                           {"interface", "side", "component"},
                           s.interfaces,
                           described("Pa", "stress on the interface, in the medium on each side")});
  if (spec.von_mises_interfaces)
    d.variables.push_back(
        {"von_mises_interfaces",
         {"interface", "side"},
         s.interfaces_von_mises,
         described("Pa", "von Mises stress on the interface, in the medium on each side")});
}

// The stress planes (depth, component, x, y) and their von Mises stress (depth, x, y); the
// section (section_depth, component, x) and its von Mises stress (section_depth, x); the
// interfaces' planes (add_interface_stress).
void add_stress(io::NetcdfDataset& d, const OutputSpec& spec, const StressRun& s) {
  const auto& summary = s.summary;
  d.dimensions.push_back({"component", 6, {}, {{{"names", "xx yy zz yz xz xy"}}, {}}});
  if (spec.stress || spec.von_mises) {
    const auto depths = summary.at("depths").get<std::vector<double>>();
    d.dimensions.push_back(
        {"depth", depths.size(), depths, described("m", "depth below the surface")});
  }
  if (spec.stress)
    d.variables.push_back({"stress", {"depth", "component"}, s.stress, described("Pa", "stress")});
  if (spec.von_mises)
    d.variables.push_back(
        {"von_mises", {"depth"}, s.von_mises, described("Pa", "von Mises stress")});
  add_interface_stress(d, spec, s);
  if (!spec.stress_section && !spec.von_mises_section) return;
  const auto nz = summary.at("section").at("nz").get<std::size_t>();
  const double depth_max = summary.at("section").at("depth_max").get<double>();
  std::vector<double> z;
  for (std::size_t k = 1; k <= nz; ++k) z.push_back(depth_max * double(k) / double(nz));
  d.dimensions.push_back({"section_depth", nz, z, described("m", "depth of the section's rows")});
  if (spec.stress_section)
    d.variables.push_back({"stress_section",
                           {"section_depth", "component", "x"},
                           s.section,
                           described("Pa", "stress on the section y = y_centre"),
                           false});
  if (spec.von_mises_section)
    d.variables.push_back({"von_mises_section",
                           {"section_depth", "x"},
                           s.section_von_mises,
                           described("Pa", "von Mises stress on the section"),
                           false});
}
// A partial slip's fields: the last step's, or a path's stacked over the dimension "step" (with
// the tangential load and shift of each step); stick as 0 or 1. `store` keeps the arrays alive.
void add_partial_slip(io::NetcdfDataset& d, const OutputSpec& spec, const SceneRun& run,
                      std::vector<std::vector<double>>& store) {
  const PartialSlipFields& f = *run.partial_slip;
  const bool path = spec.fretting;
  std::vector<std::string> leading;
  if (path) {
    const auto& rows = run.summary.at("fretting").at("steps");
    std::vector<double>& loads = store.emplace_back();
    std::vector<double>& shifts = store.emplace_back();
    for (const auto& row : rows) {
      loads.push_back(row.at("tangential_load").get<double>());
      shifts.push_back(row.at("tangential_shift").get<double>());
    }
    d.dimensions.push_back({"step", rows.size(), {}, {}});
    d.variables.push_back(
        {"tangential_load", {"step"}, loads, described("N", "tangential load"), false});
    d.variables.push_back(
        {"tangential_shift", {"step"}, shifts, described("m", "tangential shift"), false});
    leading = {"step"};
  }
  const auto add = [&](const char* name, const std::vector<Field>& fields) {
    std::vector<double>& data = store.emplace_back();
    data = path ? stacked_fields(fields)
                : std::vector<double>(fields.back().data(),
                                      fields.back().data() + fields.back().size());
    d.variables.push_back(field_variable(name, data, leading));
  };
  if (spec.shear) add("shear_x", f.shear_x), add("shear_y", f.shear_y);
  if (spec.slip) add("slip_x", f.slip_x), add("slip_y", f.slip_y);
  if (spec.stick) {
    std::vector<Field> masks;
    for (const StickMask& m : f.stick) masks.push_back(m.cast<double>());
    add("stick", masks);
  }
}

}  // namespace

io::NetcdfDataset run_dataset(const Grid& grid, const nlohmann::json& summary) {
  const bool periodic = summary.value("boundary", "free") == "periodic";
  return {grid, periodic, {}, {}, {{{"summary", summary.dump()}}, {}}};
}

io::NetcdfVariable field_variable(std::string_view name, std::span<const double> values,
                                  std::vector<std::string> leading) {
  static const std::map<std::string_view, io::NetcdfAttributes> attributes = {
      {"uz", described("m", "normal surface displacement, into the body")},
      {"pressure", described("Pa", "surface pressure")},
      {"gap", described("m", "gap after loading")},
      {"ux", described("m", "surface displacement along x")},
      {"uy", described("m", "surface displacement along y")},
      {"shear_x", described("Pa", "tangential traction along x on the body's surface")},
      {"shear_y", described("Pa", "tangential traction along y on the body's surface")},
      {"slip_x", described("m", "slip along x over the step")},
      {"slip_y", described("m", "slip along y over the step")},
      {"stick", described("1", "1 where the contact sticks, 0 elsewhere")},
      {"plastic", described("m", "plastic depth: permanent, into the body")},
      {"residual_gap", described("m", "gap the permanent surface leaves at zero load")}};
  return {std::string(name), std::move(leading), values, attributes.at(name)};
}

io::NetcdfVariable field_variable(std::string_view name, const Field& field) {
  return field_variable(name, values(field));
}

void write_run_netcdf(const std::filesystem::path& path, const OutputSpec& spec,
                      const SceneRun& run) {
  io::NetcdfDataset d = run_dataset(run.grid, run.summary);
  std::vector<double> uz, pressure, gap, loads, approaches;
  if (run.sweep) {
    const auto& rows = run.summary.at("sweep");
    for (const auto& row : rows) {
      loads.push_back(row.at("load").get<double>());
      if (!row.at("approach").is_null()) approaches.push_back(row.at("approach").get<double>());
    }
    d.dimensions.push_back({"sweep", rows.size(), {}, {}});
    d.variables.push_back({"load", {"sweep"}, loads, described("N", "total load"), false});
    if (approaches.size() == loads.size())
      d.variables.push_back({"approach", {"sweep"}, approaches, described("m", "approach"), false});
  }
  const std::vector<std::string> sweep =
      run.sweep ? std::vector<std::string>{"sweep"} : std::vector<std::string>{};
  if (spec.uz)
    d.variables.push_back(
        field_variable("uz", run.sweep ? stacked(run.sweep->uz, uz) : values(run.uz), sweep));
  if (spec.pressure)
    d.variables.push_back(field_variable(
        "pressure", run.sweep ? stacked(run.sweep->pressure, pressure) : values(run.pressure),
        sweep));
  if (spec.gap && (run.gap || run.sweep))
    d.variables.push_back(
        field_variable("gap", run.sweep ? stacked(run.sweep->gap, gap) : values(*run.gap), sweep));
  std::vector<double> plastic;
  if (spec.plastic && run.plastic)
    d.variables.push_back(field_variable(
        "plastic", run.sweep ? stacked(run.sweep->plastic, plastic) : values(*run.plastic), sweep));
  if (spec.residual_gap && run.residual_gap)
    d.variables.push_back(field_variable("residual_gap", *run.residual_gap));
  if (spec.in_plane && spec.ux && run.ux) d.variables.push_back(field_variable("ux", *run.ux));
  if (spec.in_plane && spec.uy && run.uy) d.variables.push_back(field_variable("uy", *run.uy));
  if (run.stress) add_stress(d, spec, *run.stress);
  std::vector<std::vector<double>> store;
  store.reserve(16);  // the spans point into its arrays: no reallocation
  if (run.partial_slip) add_partial_slip(d, spec, run, store);
  io::write_netcdf(path, d);
}

}  // namespace coatfft::scene
