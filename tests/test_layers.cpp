#include <catch2/catch.hpp>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "layers/layer_stack.hpp"

using coatfft::Coating;
using coatfft::Interface;
using coatfft::InvalidArgument;
using coatfft::LayerStack;
using coatfft::Material;

TEST_CASE("LayerStack stores coatings top first and sums thicknesses", "[layers]") {
  const Material steel(210e9, 0.3);
  const Material tin(400e9, 0.25);
  const LayerStack bare(steel);
  CHECK(bare.is_homogeneous());
  CHECK(bare.total_thickness() == 0.0);
  CHECK(bare.substrate() == steel);

  const LayerStack stack({{tin, 2e-6, Interface::bonded}, {steel, 3e-6, Interface::frictionless}},
                         steel);
  CHECK_FALSE(stack.is_homogeneous());
  REQUIRE(stack.coatings().size() == 2);
  CHECK(stack.coatings()[0].material == tin);
  CHECK(stack.coatings()[1].interface_below == Interface::frictionless);
  // 2e-6 + 3e-6 is one rounding away from 5e-6.
  CHECK(stack.total_thickness() == Approx(5e-6).epsilon(1e-15));
}

TEST_CASE("LayerStack refuses bad coatings naming the coating (1-based)", "[layers][bad_input]") {
  const Material m(1e9, 0.3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(
      LayerStack({{m, 1e-6}, {m, -1e-6}}, m),
      Catch::Contains("coating 2: thickness = -1e-06 m") && Catch::Contains("finite and > 0"));
  CHECK_THROWS_WITH(LayerStack({{m, 0.0}}, m), Catch::Contains("coating 1: thickness = 0 m"));
  CHECK_THROWS_AS(LayerStack({{m, nan}}, m), InvalidArgument);
  CHECK_THROWS_AS(LayerStack({{m, 1e-6}, {m, 1e-6}, {m, inf}}, m), InvalidArgument);

  std::vector<Coating> many(LayerStack::max_coatings + 1, Coating{m, 1e-6});
  CHECK_THROWS_WITH(LayerStack(many, m),
                    Catch::Contains("65 coatings") && Catch::Contains("at most 64"));
  many.pop_back();
  CHECK_NOTHROW(LayerStack(many, m));
}
