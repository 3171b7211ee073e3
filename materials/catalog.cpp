#include "materials/catalog.hpp"

#include <array>

#include "core/detail/shorten.hpp"
#include "core/error.hpp"

namespace coatfft {

namespace {

struct CatalogEntry {
  std::string_view name;
  double E;   // [Pa]
  double nu;  // [-]
};

// Sources are given per entry; coating properties scatter with the deposition process, so the
// values are representative, not design data.
constexpr std::array kCatalog{
    // AISI 52100 bearing steel: ASM Handbook Vol. 1 (1990), E = 210 GPa, nu = 0.30.
    CatalogEntry{"steel", 210e9, 0.30},
    // WC-6%Co cemented carbide: ASM Handbook Vol. 2 (1990), article "Cemented Carbides":
    // E = 600-630 GPa for 6 % Co, nu = 0.22.
    CatalogEntry{"tungsten_carbide", 600e9, 0.22},
    // TiN PVD coating: Holmberg & Matthews, Coatings Tribology, 2nd ed. (2009), ch. 2 (property
    // ranges of PVD TiN: E = 250-600 GPa); 400 GPa is a typical nanoindentation value, nu = 0.25.
    CatalogEntry{"titanium_nitride", 400e9, 0.25},
    // Hydrogenated diamond-like carbon (a-C:H): Robertson, Mater. Sci. Eng. R 37 (2002) 129,
    // E = 100-300 GPa; mid value 200 GPa, nu = 0.22.
    CatalogEntry{"dlc", 200e9, 0.22},
    // Sintered alpha-alumina: Munro, J. Am. Ceram. Soc. 80 (1997) 1919, E = 416 GPa, nu = 0.231.
    CatalogEntry{"alumina", 416e9, 0.231},
    // Aluminium alloy 6061-T6: ASM Handbook Vol. 2 (1990), E = 68.9 GPa, nu = 0.33.
    CatalogEntry{"aluminium", 68.9e9, 0.33},
    // PEEK (unfilled, Victrex 450G datasheet): tensile modulus 3.7 GPa, nu = 0.40.
    CatalogEntry{"peek", 3.7e9, 0.40},
    // PTFE: DuPont Teflon PTFE properties handbook, E ~ 0.5 GPa, nu = 0.46.
    CatalogEntry{"ptfe", 0.5e9, 0.46},
};

}  // namespace

Material material_by_name(std::string_view name) {
  for (const auto& entry : kCatalog) {
    if (entry.name == name) return Material(entry.E, entry.nu);
  }
  std::string known;
  for (const auto& entry : kCatalog) known += (known.empty() ? "" : ", ") + std::string(entry.name);
  throw InvalidArgument(
      detail::concat("unknown material \"", detail::shorten(name), "\" (known: ", known, ")"));
}

std::vector<std::string> material_names() {
  std::vector<std::string> names;
  for (const auto& entry : kCatalog) names.emplace_back(entry.name);
  return names;
}

}  // namespace coatfft
