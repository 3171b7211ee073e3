#include "scene/detail/scene_body.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "convolution/method.hpp"
#include "core/error.hpp"
#include "scene/detail/section_reader.hpp"
#include "scene/frf_table_file.hpp"

namespace coatfft::scene {

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

std::optional<LayerStack> read_optional_body(const toml::table& root) {
  if (root.contains("frf") && !root.contains("substrate") && !root.contains("coating"))
    return std::nullopt;
  return read_body(root);
}

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

}  // namespace coatfft::scene
