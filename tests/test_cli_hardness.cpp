// [contact] hardness and unload: the capped contact's files and summary keys, a sweep loaded and
// unloaded (the plastic depth kept, the residual gap), the stresses under the capped pressure,
// and the refusals.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

// A rigid sphere (R = 1 mm) on steel under 2 um of TiN, 32 x 32 cells over 80 um: at 2 N the
// elastic peak pressure is about 3 GPa, so a hardness of 2.5 GPa caps a plastic disk.
const std::string kCapped = R"([grid]
nx = 32
ny = 32
lx = 80e-6
ly = 80e-6
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 2.0e-6
interface = "bonded"
[contact]
indenter = "sphere"
radius = 1.0e-3
load = 2.0
hardness = 2.5e9
[method]
name = "frf-split"
)";

const std::string kCycle = R"(load = [0.5, 1.0, 2.0]
hardness = 2.5e9
unload = true)";

}  // namespace

TEST_CASE("hardness: the capped contact's files and summary", "[cli_hardness]") {
  const fs::path out = run_scene_ok(kCapped, "capped");
  CHECK(npy_shape(out / "plastic.npy") == "(32, 32)");
  CHECK_FALSE(fs::exists(out / "residual_gap.npy"));  // no unloading
  const nlohmann::json s = read_summary(out);
  REQUIRE(s["converged"] == true);
  const nlohmann::json& p = s["plastic"];
  for (const char* key :
       {"hardness", "plastic_area", "plastic_area_fraction", "max_plastic_depth", "plastic_volume"})
    CHECK(p.contains(key));
  CHECK(s["max_pressure"].get<double>() == 2.5e9);
  const std::vector<double> pressure = npy_values(out / "pressure.npy");
  const std::vector<double> depth = npy_values(out / "plastic.npy");
  const std::vector<double> gap = npy_values(out / "gap.npy");
  const double cell = std::pow(80e-6 / 32, 2);
  double at_cap = 0, volume = 0, deepest = 0;
  for (std::size_t k = 0; k < pressure.size(); ++k) {
    REQUIRE(pressure[k] <= 2.5e9);
    // The depth is the overlap of the cells at the hardness, and only of those.
    if (pressure[k] == 2.5e9) {
      ++at_cap;
      CHECK(depth[k] == -gap[k]);
    } else {
      CHECK(depth[k] == 0.0);
    }
    volume += depth[k] * cell;
    deepest = std::max(deepest, depth[k]);
  }
  CHECK(at_cap > 0);
  CHECK(p["plastic_area"].get<double>() == Approx(at_cap * cell).epsilon(1e-12));
  CHECK(p["plastic_area_fraction"].get<double>() ==
        Approx(at_cap * cell / s["contact_area"].get<double>()).epsilon(1e-12));
  CHECK(p["plastic_volume"].get<double>() == Approx(volume).epsilon(1e-12));
  CHECK(p["max_plastic_depth"].get<double>() == deepest);
}

TEST_CASE("hardness and unload: a sweep loaded and unloaded keeps its plastic depth",
          "[cli_hardness]") {
  const fs::path out =
      run_scene_ok(kCapped, "capped_cycle", "load = 2.0\nhardness = 2.5e9", kCycle);
  CHECK(npy_shape(out / "plastic.npy") == "(5, 32, 32)");
  CHECK(npy_shape(out / "pressure.npy") == "(5, 32, 32)");
  CHECK(npy_shape(out / "residual_gap.npy") == "(32, 32)");
  const std::vector<std::string> rows = lines_of(out / "sweep.csv");
  REQUIRE(rows.size() == 6);
  CHECK(rows[0].ends_with(",max_penetration,plastic_area,phase,cohesive_area"));
  const std::vector<std::string> phases{"load", "load", "load", "unload", "unload"};
  for (std::size_t k = 0; k < phases.size(); ++k)
    CHECK(rows[k + 1].ends_with("," + phases[k] + ",0"));
  const nlohmann::json s = read_summary(out);
  REQUIRE(s["converged"] == true);
  const nlohmann::json& sweep = s["sweep"];
  const std::vector<double> loads{0.5, 1.0, 2.0, 1.0, 0.5};
  for (std::size_t k = 0; k < loads.size(); ++k)
    CHECK(sweep[k]["load"].get<double>() == Approx(loads[k]).epsilon(1e-12));
  CHECK(sweep[2]["plastic_area"].get<double>() > 0);   // the peak flows
  CHECK(sweep[4]["plastic_area"].get<double>() == 0);  // unloading is elastic
  // The depth never decreases along the history; the residual gap is the heights plus the last
  // depth, touching at zero.
  const std::vector<double> depth = npy_values(out / "plastic.npy");
  const std::size_t n = 32 * 32;
  for (std::size_t step = 1; step < 5; ++step)
    for (std::size_t k = 0; k < n; ++k) REQUIRE(depth[step * n + k] >= depth[(step - 1) * n + k]);
  const std::vector<double> residual = npy_values(out / "residual_gap.npy");
  CHECK(*std::min_element(residual.begin(), residual.end()) == 0.0);
  const double deepest = *std::max_element(depth.begin() + 4 * n, depth.end());
  CHECK(deepest > 0);
  CHECK(s["plastic"]["max_plastic_depth"].get<double>() == deepest);
}

TEST_CASE("hardness: the stresses of the capped pressure", "[cli_hardness]") {
  const fs::path out = run_scene_ok(kCapped, "capped_stress", "[method]",
                                    "[stress]\ndepths = [1e-6, 4e-6]\nalpha = 4\n[method]");
  CHECK(npy_shape(out / "stress.npy") == "(2, 6, 32, 32)");
  const nlohmann::json s = read_summary(out);
  CHECK(s["converged"] == true);
  CHECK(s.contains("stress"));
  CHECK(s["max_pressure"].get<double>() == 2.5e9);
}

TEST_CASE("hardness and unload: refusals", "[cli_hardness]") {
  const std::string h = "hardness = 2.5e9";
  for (const BadCase& c :
       {BadCase{"hard_zero", h, "hardness = 0.0", "must be finite and > 0"},
        BadCase{"hard_negative", h, "hardness = -1e9", "must be finite and > 0"},
        BadCase{"hard_nan", h, "hardness = nan", "must be finite"},
        BadCase{"hard_text", h, "hardness = \"hard\"", "hardness"},
        BadCase{"hard_domain", "load = 2.0", "load = 20.0", "whole domain at the hardness"},
        BadCase{"unload_one", h, h + "\nunload = true", "needs a list"},
        BadCase{"unload_elastic", "load = 2.0\nhardness = 2.5e9",
                "load = [1.0, 2.0]\nunload = true", "needs hardness"},
        BadCase{"hard_friction", h, h + "\nfriction = 0.3", "not combined with friction"},
        BadCase{"plastic_elastic", h, "[output]\nfields = [\"plastic\"]",
                "\"plastic\" needs a capped contact"},
        BadCase{"residual_one", "[method]", "[output]\nfields = [\"residual_gap\"]\n[method]",
                "\"residual_gap\" needs an unloading sweep"}})
    check_refused(kCapped, c);
}

TEST_CASE("hardness on a body given by its [frf] table: the body given by its layers",
          "[cli_hardness]") {
  // tabulated_frf.csv tabulates TiN 100 um on steel (examples/scenes/tabulated_frf.toml): the
  // capped sphere on the table and on the layers agree to the table's interpolation.
  const std::string table = std::string(COATFFT_SOURCE_DIR) + "/examples/scenes/tabulated_frf.csv";
  const std::string layered = R"([grid]
nx = 32
ny = 32
lx = 4.0e-3
ly = 4.0e-3
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 1.0e-4
interface = "bonded"
[contact]
indenter = "sphere"
radius = 0.05
load = 100.0
hardness = 0.3e9
[method]
name = "frf-split"
)";
  const std::string tabulated = std::string(layered).replace(
      layered.find("[substrate]"), layered.find("[contact]") - layered.find("[substrate]"),
      "[frf]\npath = \"" + table + "\"\n");
  const fs::path a = run_scene_ok(layered, "capped_layers");
  const fs::path b = run_scene_ok(tabulated, "capped_table");
  const std::vector<double> pa = npy_values(a / "pressure.npy"),
                            pb = npy_values(b / "pressure.npy");
  const std::vector<double> da = npy_values(a / "plastic.npy"), db = npy_values(b / "plastic.npy");
  double p_diff = 0, d_diff = 0, deepest = 0;
  for (std::size_t k = 0; k < pa.size(); ++k) {
    p_diff = std::max(p_diff, std::abs(pa[k] - pb[k]));
    d_diff = std::max(d_diff, std::abs(da[k] - db[k]));
    deepest = std::max(deepest, da[k]);
  }
  CHECK(deepest > 0);
  // Measured 8e-10 of H and 4e-10 of the depth at 64^2 (the table's spline against the FRF).
  CHECK(p_diff < 1e-7 * 0.3e9);
  CHECK(d_diff < 1e-7 * deepest);
}
