#include <catch2/catch.hpp>
#include <limits>

#include "core/error.hpp"
#include "materials/catalog.hpp"
#include "materials/material.hpp"

using coatfft::InvalidArgument;
using coatfft::Material;

TEST_CASE("Material derived moduli follow their definitions", "[material]") {
  const Material m(200e9, 0.25);
  CHECK(m.plane_strain_modulus() == Approx(200e9 / (1 - 0.0625)).epsilon(1e-15));
  CHECK(m.shear_modulus() == Approx(80e9).epsilon(1e-15));
  CHECK(m.kolosov() == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("Material refuses bad values naming them", "[material][bad_input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(Material(-1e9, 0.3), Catch::Contains("E = -1e+09"));
  CHECK_THROWS_AS(Material(0.0, 0.3), InvalidArgument);
  CHECK_THROWS_AS(Material(nan, 0.3), InvalidArgument);
  CHECK_THROWS_WITH(Material(1e9, 0.5), Catch::Contains("nu = 0.5"));
  CHECK_THROWS_AS(Material(1e9, -1.0), InvalidArgument);
  CHECK_THROWS_AS(Material(1e9, nan), InvalidArgument);
  CHECK_NOTHROW(Material(1e9, 0.4999));
  CHECK_NOTHROW(Material(1e9, -0.9));
}

TEST_CASE("Material catalogue holds the named engineering materials", "[material]") {
  for (const char* name : {"steel", "tungsten_carbide", "titanium_nitride", "dlc", "alumina",
                           "aluminium", "peek", "ptfe"}) {
    INFO(name);
    CHECK_NOTHROW(coatfft::material_by_name(name));
  }
  CHECK(coatfft::material_by_name("steel") == Material(210e9, 0.3));
  CHECK_THROWS_WITH(coatfft::material_by_name("unobtainium"),
                    Catch::Contains("unobtainium") && Catch::Contains("steel"));
}
