// The stress summary of a [stress] scene (scene/scene_stress.hpp): the maxima per medium against
// Johnson's (1985) closed forms on the axis of Hertz's pressure.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "loads/hertz_pressure.hpp"
#include "scene/scene_stress.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

// Johnson (1985) eq. 3.45 on the axis of Hertz's pressure (p0 = 1, a = 1) at depth z/a in a
// half-space of Poisson ratio nu: von Mises = |sigma_zz - sigma_rr| (sigma_tt = sigma_rr there),
// twice Tresca's maximum shear stress.
double axis_von_mises(double z, double nu) {
  const double szz = -1.0 / (1 + z * z);
  const double srr = -((1 + nu) * (1 - z * std::atan(1 / z)) - 0.5 / (1 + z * z));
  return std::abs(szz - srr);
}

}  // namespace

TEST_CASE("stress summary: the maxima of each medium, an interface counted on both sides",
          "[scene_stress]") {
  // A coating of the substrate's own material, h = 0.3 a: the half-space, whose von Mises stress
  // grows along the axis down to its maximum 0.62 p0 at z = 0.48 a. The coating's maximum is
  // then on its bottom face (the interface from above), the substrate's on the plane 0.48 a.
  const double a = 1e-3, h = 0.3 * a, nu = steel.poisson_ratio();
  const Grid grid(65, 65, 4 * a, 4 * a);
  const LayerStack body({{steel, h, Interface::bonded}}, steel);
  scene::StressSpec spec;
  spec.depths = {0.1 * a, 0.48 * a};
  spec.alpha = 4;
  const Field p = hertz_pressure(grid, 1.0, a, Sampling::cell_average);
  scene::ProgressObserver silent;
  const scene::StressRun run = scene::compute_stress(spec, body, grid, p, {}, 1, silent);
  const auto& s = run.summary;
  CHECK(s["planes"] == 4);  // two depths and the interface from both sides
  REQUIRE(s["layers"].size() == 2);
  CHECK(s["layers"][0]["medium"] == "coating 1");
  CHECK(s["layers"][1]["medium"] == "substrate");
  // The load's discretisation at dx = a/16 and the periodic images at alpha = 4: a few 1e-3 p0
  // (tests/test_stress_operator.cpp: 3e-4 at a/32, alpha 8); measured here 1.0e-3.
  const double tolerance = 3e-3;
  for (const auto& [layer, z] : {std::pair{0, 0.3}, std::pair{1, 0.48}}) {
    INFO("layer " << layer);
    for (const auto& [key, share] : {std::pair{"max_von_mises", 1.0}, {"max_tresca", 0.5}}) {
      const auto& peak = s["layers"][layer][key];
      CHECK(std::abs(peak["value"].get<double>() - share * axis_von_mises(z, nu)) < tolerance);
      CHECK(peak["z"].get<double>() == Approx(z * a).epsilon(1e-12));
      CHECK(std::abs(peak["x"].get<double>()) < 1e-12);
      CHECK(std::abs(peak["y"].get<double>()) < 1e-12);
    }
  }
  // The body's maxima are the largest of the media's: the substrate's, on its plane 0.48 a.
  CHECK(s["max_von_mises"]["value"] == s["layers"][1]["max_von_mises"]["value"]);
  CHECK(s["max_tresca"]["value"] == s["layers"][1]["max_tresca"]["value"]);
  // Hertz's largest tension is at the surface, (1 - 2 nu)/3 p0 at r = a: below it, smaller.
  for (int layer : {0, 1})
    CHECK(s["layers"][layer]["max_principal_tensile"]["value"].get<double>() < (1 - 2 * nu) / 3);
  REQUIRE(s["interfaces"].size() == 1);
  CHECK(s["interfaces"][0]["depth"].get<double>() == Approx(h).epsilon(1e-12));
}
