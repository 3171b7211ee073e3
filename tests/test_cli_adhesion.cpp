// [contact] adhesion = "dugdale": an approach sweep up and back down through pull-off (the
// files, sweep.csv's phase and cohesive_area, summary.json's adhesion against Maugis-Dugdale's
// pull-off), and the refusals.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli_process.hpp"
#include "validation/maugis_dugdale.hpp"

using namespace coatfft_test;

namespace {

// A rigid sphere (R = 1 mm) on a soft half-space (E* = 1 GPa), w = 0.05 J/m^2 and h0 = 15.3 nm:
// Maugis' lambda = 1. 128 x 128 cells over 60 um (a_s / dx = 10.5).
const std::string kAdhesive = R"([grid]
nx = 128
ny = 128
lx = 60e-6
ly = 60e-6
[substrate]
E = 0.91e9
nu = 0.3
[contact]
indenter = "sphere"
radius = 1.0e-3
approach = [-0.1e-6, -0.05e-6, 0.0, 0.2e-6, 0.4e-6]
adhesion = "dugdale"
work_of_adhesion = 0.05
adhesion_range = 15.3e-9
unload = true
)";

}  // namespace

TEST_CASE("adhesion: an approach sweep up and down through pull-off", "[cli_adhesion]") {
  const fs::path out = run_scene_ok(kAdhesive, "adhesive");
  CHECK(npy_shape(out / "pressure.npy") == "(9, 128, 128)");
  const std::vector<std::string> rows = lines_of(out / "sweep.csv");
  REQUIRE(rows.size() == 10);
  CHECK(rows[0].ends_with(",phase,cohesive_area"));
  const nlohmann::json s = read_summary(out);
  REQUIRE(s["converged"] == true);
  const nlohmann::json& a = s["adhesion"];
  for (const char* key :
       {"model", "work_of_adhesion", "adhesion_range", "cohesive_stress", "pull_off_load",
        "pull_off_approach", "contact_area", "cohesive_area", "rounds", "jumped_off_at", "lambda"})
    CHECK(a.contains(key));
  CHECK(a["lambda"].get<double>() == Approx(1.0).epsilon(1e-3));
  // The most tensile load of the rows, and tension on the cells: p >= -sigma0 everywhere.
  double most_tensile = 0;
  for (const nlohmann::json& row : s["sweep"])
    most_tensile = std::min(most_tensile, row["load"].get<double>());
  CHECK(a["pull_off_load"].get<double>() == most_tensile);
  const double sigma0 = a["cohesive_stress"].get<double>();
  for (const double p : npy_values(out / "pressure.npy")) REQUIRE(p >= -sigma0 * (1 + 1e-12));
  // Maugis-Dugdale's pull-off is -1.60 pi w R: this coarse path (steps of 0.2 d_s) and grid
  // (a_s / dx = 10.5) see 0.94 of it (the path's most tensile step, not the curve's minimum).
  const double md = coatfft::MaugisDugdale(1e-3, 1e9, 0.05, 15.3e-9).pull_off_load();
  CHECK(most_tensile / md > 0.85);
  CHECK(most_tensile / md < 1.1);
  // Leaving the surface: the last rows carry nothing, and the jump is reported.
  CHECK(s["sweep"][8]["load"].get<double>() == 0.0);
  CHECK(a["jumped_off_at"].is_number());
}

TEST_CASE("adhesion: refusals", "[cli_adhesion]") {
  const std::string w = "work_of_adhesion = 0.05";
  const std::string r = "adhesion_range = 15.3e-9";
  for (const BadCase& c :
       {BadCase{"adh_w_zero", w, "work_of_adhesion = 0.0", "must be finite and > 0"},
        BadCase{"adh_w_negative", w, "work_of_adhesion = -0.05", "must be finite and > 0"},
        BadCase{"adh_range_zero", r, "adhesion_range = 0.0", "must be finite and > 0"},
        BadCase{"adh_model", "adhesion = \"dugdale\"", "adhesion = \"jkr\"", "dugdale"},
        BadCase{"adh_negative_elastic",
                "adhesion = \"dugdale\"\n" + w + "\n" + r + "\nunload = true", "",
                "must be > 0 (zero or negative only with adhesion)"},
        BadCase{"adh_hardness", r, r + "\nhardness = 1e9", "not combined"},
        BadCase{"adh_friction", r, r + "\nfriction = 0.3", "not combined with friction"},
        BadCase{"adh_range_alone",
                "approach = [-0.1e-6, -0.05e-6, 0.0, 0.2e-6, 0.4e-6]\nadhesion = \"dugdale\"",
                "approach = 0.2e-6", "needs adhesion"},
        BadCase{"adh_pull_off_load", "approach = [-0.1e-6, -0.05e-6, 0.0, 0.2e-6, 0.4e-6]",
                "load = [-0.01, 0.001]", "past pull-off"}})
    check_refused(kAdhesive, c);
}

TEST_CASE("adhesion: the stresses under the adhesive tractions", "[cli_adhesion]") {
  // One approach in contact on a 32^2 grid; [stress] on a plane half a cell deep (a shallower one
  // costs seconds of quadrature): sigma_zz there is near the surface traction, -p (Johnson 1985,
  // the boundary condition), so tensile (> 0) under the cohesive zone's cells.
  std::string scene = kAdhesive;
  scene.replace(scene.find("nx = 128\nny = 128"), 17, "nx = 32\nny = 32");
  scene.replace(scene.find("approach = [-0.1e-6, -0.05e-6, 0.0, 0.2e-6, 0.4e-6]"), 51,
                "approach = 0.2e-6");
  scene.replace(scene.find("unload = true"), 13, "[stress]\ndepths = [1e-6]\nalpha = 4");
  const fs::path out = run_scene_ok(scene, "adhesive_stress");
  const nlohmann::json s = read_summary(out);
  REQUIRE(s["converged"] == true);
  const std::vector<double> p = npy_values(out / "pressure.npy");
  const std::vector<double> stress = npy_values(out / "stress.npy");
  const std::size_t n = p.size();
  REQUIRE(stress.size() == 6 * n);
  const double sigma0 = s["adhesion"]["cohesive_stress"].get<double>();
  int tensile = 0, pulled = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (p[k] != -sigma0) continue;  // the cohesive zone's cells
    ++pulled;
    tensile += stress[2 * n + k] > 0 ? 1 : 0;
  }
  INFO(pulled << " cells pulled, " << tensile << " in tension below");
  REQUIRE(pulled > 0);
  // Every cell of the zone pulls the plane below into tension.
  CHECK(tensile == pulled);
}
