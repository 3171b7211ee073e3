// [contact] load and approach as lists (a sweep): the stacked fields, sweep.csv and the summary,
// each value against a run of its own, and the refusals.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

// A paraboloid on a periodic steel surface (32^2 cells): the contacts stay far from the border.
const std::string kSweep = R"([grid]
nx = 32
ny = 32
lx = 3.0e-3
ly = 3.0e-3
boundary = "periodic"
[substrate]
material = "steel"
[contact]
indenter = "paraboloid"
radius = 0.01
load = [40.0, 10.0, 20.0]
)";

}  // namespace

TEST_CASE("[contact] load = [...] solves a sweep: every value as its own run", "[cli_sweep]") {
  const fs::path out = run_scene_ok(kSweep, "sweep");
  for (const char* name : {"pressure.npy", "uz.npy", "gap.npy"})
    CHECK(npy_shape(out / name) == "(3, 32, 32)");
  CHECK_FALSE(fs::exists(out / "displacement.csv"));
  const nlohmann::json s = read_summary(out);
  REQUIRE(s["sweep"].size() == 3);
  CHECK(s["converged"] == true);
  const std::vector<std::string> csv = lines_of(out / "sweep.csv");
  REQUIRE(csv.size() == 4);
  // The columns scripts read by position stay first; later ones are appended.
  CHECK(csv[0] ==
        "load,approach,area_fraction,max_pressure,mean_gap,iterations,operator_applications,"
        "converged,max_penetration,plastic_area,phase,cohesive_area");
  for (int k = 1; k <= 3; ++k) CHECK(csv[k].ends_with(",0,load,0"));  // elastic, loading
  const std::vector<double> sweep_p = npy_values(out / "pressure.npy");
  const double loads[3] = {10.0, 20.0, 40.0};  // ascending
  for (int k = 0; k < 3; ++k) {
    INFO("load " << loads[k]);
    const nlohmann::json& row = s["sweep"][k];
    CHECK(row["load"].get<double>() == Approx(loads[k]).epsilon(1e-12));
    CHECK(std::stod(csv[k + 1]) == row["load"].get<double>());  // the CSV at full precision
    CHECK(row["converged"] == true);
    // The same value alone: the same solution to the solver's tolerance.
    std::string alone = kSweep;
    alone.replace(alone.find("load = [40.0, 10.0, 20.0]"), 25,
                  "load = " + std::to_string(loads[k]));
    const fs::path one = run_scene_ok(alone, "sweep_one_" + std::to_string(k));
    const std::vector<double> p = npy_values(one / "pressure.npy");
    double max_p = 0, diff = 0;
    for (std::size_t c = 0; c < p.size(); ++c) {
      max_p = std::max(max_p, p[c]);
      diff = std::max(diff, std::abs(p[c] - sweep_p[k * p.size() + c]));
    }
    CHECK(diff < 1e-8 * max_p);
    CHECK(row["area_fraction"].get<double>() * 3e-3 * 3e-3 ==
          Approx(read_summary(one)["contact_area"].get<double>()).epsilon(1e-12));
  }
  // The summary's other contact keys are the largest value's.
  CHECK(s["load"].get<double>() == s["sweep"][2]["load"].get<double>());
}

TEST_CASE("a sweep refuses what takes one load, and bad lists", "[cli_sweep]") {
  const BadCase cases[] = {
      {"sweep_empty", "load = [40.0, 10.0, 20.0]", "load = []", "a sweep takes 1 to 256"},
      {"sweep_negative", "load = [40.0, 10.0, 20.0]", "load = [40.0, -1.0]", "must be > 0"},
      {"sweep_text", "load = [40.0, 10.0, 20.0]", "load = [40.0, \"a\"]", "list of numbers"},
      {"sweep_friction", "load = [40.0, 10.0, 20.0]", "load = [40.0, 10.0]\nfriction = 0.2",
       "friction takes one load"},
      {"sweep_csv", "load = [40.0, 10.0, 20.0]",
       "load = [40.0, 10.0]\n[output]\nfields = [\"displacement_csv\"]", "holds one field"},
  };
  for (const BadCase& c : cases) check_refused(kSweep, c);
  // [stress] (on a free surface: a periodic one refuses it on its own ground).
  std::string free = kSweep;
  free.erase(free.find("boundary = \"periodic\"\n"), 22);
  check_refused(free,
                {"sweep_stress", "load = [40.0, 10.0, 20.0]",
                 "load = [40.0, 10.0]\n[stress]\ndepths = [1e-4]", "[stress] takes one load"});
  std::string many = "load = [1.0";
  for (int k = 2; k <= 257; ++k) many += ", " + std::to_string(k) + ".0";
  check_refused(kSweep, {"sweep_many", "load = [40.0, 10.0, 20.0]", many + "]", "1 to 256"});
}

TEST_CASE("a sweep's refusals name the key and the value they concern", "[cli_sweep]") {
  // The contact reaches the domain edge from the second value on (a free 3 mm square under a
  // 10 mm sphere: 10 N stays inside it, 1 MN does not): the refusal names that value.
  std::string free = kSweep;
  free.erase(free.find("boundary = \"periodic\"\n"), 22);
  const ProcessResult edge = check_refused(
      free, {"sweep_edge", "load = [40.0, 10.0, 20.0]", "load = [10.0, 1e6, 2e6]", "domain edge"});
  CHECK(edge.stderr_text.find("(first at [contact] load = 1e+06 N, value 2 of the sweep's 3)") !=
        std::string::npos);
  // A value beyond what double precision solves: named as the scene's key, not the solver's.
  const ProcessResult far = check_refused(
      kSweep, {"sweep_far", "load = [40.0, 10.0, 20.0]", "load = [10.0, 1e300]", "displaces"});
  CHECK(far.stderr_text.find("[contact] load = 1e+300 N displaces") != std::string::npos);
  CHECK(far.stderr_text.find("ContactSolver") == std::string::npos);
}
