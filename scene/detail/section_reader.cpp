#include "scene/detail/section_reader.hpp"

#include "materials/catalog.hpp"

namespace coatfft::scene {

const toml::table& section(const toml::table& root, std::string_view name, bool required) {
  static const toml::table empty;
  const toml::node* node = root.get(name);
  COATFFT_REQUIRE(node != nullptr || !required, "missing required section [", name, "]");
  if (node == nullptr) return empty;
  COATFFT_REQUIRE(node->is_table(), "[", name, "] must be a table");
  return *node->as_table();
}

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

double positive(SectionReader& reader, std::string_view key) {
  const double value = reader.number(key);
  COATFFT_REQUIRE(value > 0, reader.where(key), " = ", value, " must be > 0");
  return value;
}

}  // namespace coatfft::scene
