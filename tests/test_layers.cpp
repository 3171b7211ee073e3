#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <tuple>
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

TEST_CASE("LayerStack::interface_depths are the running sums of the thicknesses", "[layers]") {
  const Material m(1e9, 0.3);
  CHECK(LayerStack(m).interface_depths().empty());
  const LayerStack stack({{m, 10e-6}, {m, 20e-6}}, m);
  REQUIRE(stack.interface_depths().size() == 2);
  CHECK(stack.interface_depths()[0] == 10e-6);
  // The rounding this is all about: the sum is not the decimal 3e-5.
  CHECK(stack.interface_depths()[1] == 10e-6 + 20e-6);
  CHECK(stack.interface_depths()[1] != 30e-6);
  CHECK(stack.total_thickness() == stack.interface_depths()[1]);
}

TEST_CASE("LayerStack::locate takes a typed depth equal to a running sum as the interface",
          "[layers][locate]") {
  const Material m(1e9, 0.3);
  using coatfft::InterfaceSide;
  // 10e-6 + 20e-6 = 3.0000000000000004e-5 (one ulp above 3e-5), 7e-6 + 3e-6 =
  // 9.999999999999999e-6 (one below 1e-5): the typed depth is the interface on either side.
  const LayerStack up({{m, 10e-6}, {m, 20e-6}}, m);
  const LayerStack down({{m, 7e-6}, {m, 3e-6}, {m, 5e-6}}, m);
  REQUIRE(10e-6 + 20e-6 > 30e-6);
  REQUIRE(7e-6 + 3e-6 < 10e-6);
  for (const auto& [stack, typed, i] :
       {std::tuple{&up, 30e-6, std::size_t(1)}, std::tuple{&down, 10e-6, std::size_t(1)}}) {
    const coatfft::DepthLocation below = stack->locate(typed, InterfaceSide::below);
    const coatfft::DepthLocation above = stack->locate(typed, InterfaceSide::above);
    CHECK(below.at_interface);
    CHECK(above.at_interface);
    CHECK(below.layer == i + 1);
    CHECK(above.layer == i);
    // Evaluated at the interface's own depth, not the typed one.
    CHECK(below.depth == stack->interface_depths()[i]);
    CHECK(above.depth == stack->interface_depths()[i]);
  }
  // Inside a medium: its index, the depth unchanged; the surface lies in the first medium.
  for (const InterfaceSide side : {InterfaceSide::above, InterfaceSide::below}) {
    CHECK(up.locate(0.0, side).layer == 0);
    CHECK_FALSE(up.locate(0.0, side).at_interface);
    CHECK(up.locate(5e-6, side).layer == 0);
    CHECK(up.locate(29e-6, side).layer == 1);
    CHECK(up.locate(31e-6, side).layer == 2);
    CHECK(up.locate(31e-6, side).depth == 31e-6);
    CHECK_FALSE(up.locate(31e-6, side).at_interface);
    CHECK(LayerStack(m).locate(1e-3, side).layer == 0);
  }
  // Just outside the tolerance is a depth inside a medium again.
  const double d = up.interface_depths()[1];
  const double outside = d * (1 + 2 * LayerStack::interface_tolerance);
  CHECK_FALSE(up.locate(outside, InterfaceSide::above).at_interface);
  CHECK(up.locate(outside, InterfaceSide::above).layer == 2);
  CHECK(up.locate(d * (1 - 2 * LayerStack::interface_tolerance), InterfaceSide::below).layer == 1);
  CHECK_THROWS_AS(up.locate(-1e-6, InterfaceSide::below), InvalidArgument);
  CHECK_THROWS_AS(up.locate(std::numeric_limits<double>::quiet_NaN(), InterfaceSide::below),
                  InvalidArgument);
}

TEST_CASE("LayerStack::locate finds every interface of random stacks from the exact sums",
          "[layers][locate]") {
  // Property: for stacks of up to max_coatings random thicknesses (three-digit decimals of
  // 1 nm ... 1 mm), the exact sum of the thicknesses rounded once and the sum accumulated in the
  // other order are the interface, on the side asked, although they often differ from the
  // running sum. (The thinnest coating is far above the tolerance: no two interfaces merge.)
  const Material m(1e9, 0.3);
  using coatfft::InterfaceSide;
  std::mt19937_64 rng(20260101);
  std::uniform_int_distribution<int> count(1, int(LayerStack::max_coatings));
  std::uniform_real_distribution<double> exponent(-9.0, -3.0);
  int differing = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Coating> coatings(std::size_t(count(rng)), Coating{m, 0.0});
    for (Coating& c : coatings) {
      char typed[32];  // a thickness as a user types it: three significant digits
      std::snprintf(typed, sizeof typed, "%.3g", std::pow(10.0, exponent(rng)));
      c.thickness = std::stod(typed);
    }
    const LayerStack stack(coatings, m);
    long double exact = 0;
    for (std::size_t i = 0; i < coatings.size(); ++i) {
      exact += coatings[i].thickness;
      double reversed = 0;
      for (std::size_t j = i + 1; j-- > 0;) reversed += coatings[j].thickness;
      for (const double z : {double(exact), reversed}) {
        differing += z != stack.interface_depths()[i];
        const auto below = stack.locate(z, InterfaceSide::below);
        const auto above = stack.locate(z, InterfaceSide::above);
        REQUIRE(below.at_interface);
        CHECK(below.layer == i + 1);
        CHECK(above.layer == i);
        CHECK(below.depth == stack.interface_depths()[i]);
      }
    }
  }
  // The property is exercised: many of these depths are not the running sums bit for bit.
  CHECK(differing > 100);
}
