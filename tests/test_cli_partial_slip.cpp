// [contact] tangential_load and tangential_shift (a partial slip): the files and summary keys, a
// Hertz contact against Cattaneo-Mindlin, a fretting path kept in the order given with its
// closed loop, and the refusals.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "materials/material.hpp"
#include "tests/cli_process.hpp"
#include "validation/cattaneo_mindlin.hpp"

using namespace coatfft_test;

namespace {

// A rigid sphere (R = 10 mm, 20 N) on a nearly incompressible half-space (nu = 0.4999: the
// tractions leave the pressure as it is, Cattaneo-Mindlin's assumption), a = 0.39 mm over 8 cells.
const std::string kSlip = R"([grid]
nx = 41
ny = 41
lx = 1.9902e-3
ly = 1.9902e-3
[substrate]
E = 2e9
nu = 0.4999
[contact]
indenter = "sphere"
radius = 0.01
load = 20.0
friction = 0.3
tangential_load = 3.0
)";

coatfft::CattaneoMindlin reference() {
  return coatfft::cattaneo_mindlin(20.0, 0.01, coatfft::Material(2e9, 0.4999), 0.3);
}

// The bytes of a uint8 .npy file after its header.
std::vector<unsigned char> npy_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t start = all.find('\n') + 1;
  return {all.begin() + static_cast<std::ptrdiff_t>(start), all.end()};
}

}  // namespace

TEST_CASE("tangential_load: a partial slip's files, against Cattaneo-Mindlin",
          "[cli_partial_slip]") {
  const fs::path out = run_scene_ok(kSlip, "partial_slip");
  for (const char* name : {"shear_x.npy", "shear_y.npy", "slip_x.npy", "slip_y.npy", "stick.npy",
                           "ux.npy", "uy.npy", "uz.npy", "pressure.npy"})
    CHECK(npy_shape(out / name) == "(41, 41)");
  CHECK_FALSE(fs::exists(out / "fretting.csv"));  // one value: no path
  const nlohmann::json s = read_summary(out);
  const nlohmann::json& p = s["partial_slip"];
  for (const char* key :
       {"tangential_load", "tangential_shift", "stick_area", "stick_radius", "slip_area",
        "max_shear", "dissipated_energy", "iterations", "operator_applications", "converged"})
    CHECK(p.contains(key));
  CHECK(p["converged"] == true);
  CHECK(s["converged"] == true);
  // The tractions carry the load: their sum times the cell area.
  const double cell = std::pow(1.9902e-3 / 41, 2);
  double sum = 0;
  for (const double q : npy_values(out / "shear_x.npy")) sum += q * cell;
  CHECK(sum == Approx(3.0).epsilon(1e-7));
  CHECK(p["tangential_load"].get<double>() == Approx(3.0).epsilon(1e-7));
  // stick.npy: uint8, its cells the stick area.
  CHECK(lines_of(out / "stick.npy")[0].find("'descr': '|u1'") != std::string::npos);
  double stuck = 0;
  for (const unsigned char b : npy_bytes(out / "stick.npy")) {
    REQUIRE(b <= 1);
    stuck += b;
  }
  CHECK(stuck * cell == Approx(p["stick_area"].get<double>()).epsilon(1e-12));
  // Cattaneo-Mindlin at Q = 0.5 mu P, a/dx = 8 (docs/contact.md, "Partial slip": the shift
  // within 0.3 %, the stick radius within a ring of cells).
  const coatfft::CattaneoMindlin cm = reference();
  CHECK(p["tangential_shift"].get<double>() == Approx(cm.shift(3.0)).epsilon(0.01));
  CHECK(p["stick_radius"].get<double>() == Approx(cm.stick_radius(3.0)).epsilon(0.12));
  CHECK(p["stick_radius"].get<double>() ==
        Approx(std::sqrt(p["stick_area"].get<double>() / std::numbers::pi)).epsilon(1e-12));
}

TEST_CASE("tangential_load = [...]: a fretting path in the order given, its loop and energy",
          "[cli_partial_slip]") {
  // 0 -> Q* -> -Q* -> Q* with Q* = 0.5 mu P, two steps a branch: not sorted.
  const fs::path out = run_scene_ok(kSlip, "fretting", "tangential_load = 3.0",
                                    "tangential_load = [1.5, 3.0, 0.0, -3.0, 0.0, 3.0]");
  for (const char* name : {"shear_x.npy", "shear_y.npy", "slip_x.npy", "slip_y.npy", "stick.npy"})
    CHECK(npy_shape(out / name) == "(6, 41, 41)");
  CHECK(npy_shape(out / "pressure.npy") == "(41, 41)");  // the last step's
  const std::vector<std::string> csv = lines_of(out / "fretting.csv");
  REQUIRE(csv.size() == 7);
  CHECK(csv[0] ==
        "step,tangential_load,tangential_shift,stick_area,slip_area,max_shear,dissipated_energy,"
        "iterations,converged");
  const nlohmann::json s = read_summary(out);
  const nlohmann::json& steps = s["fretting"]["steps"];
  REQUIRE(steps.size() == 6);
  const double loads[6] = {1.5, 3.0, 0.0, -3.0, 0.0, 3.0};
  for (int k = 0; k < 6; ++k) {
    CHECK(steps[k]["step"] == k + 1);
    CHECK(steps[k]["tangential_load"].get<double>() == Approx(loads[k]).margin(1e-7 * 6.0));
    CHECK(std::stod(csv[k + 1].substr(csv[k + 1].find(',') + 1)) ==
          steps[k]["tangential_load"].get<double>());
    CHECK(csv[k + 1].back() == '1');
  }
  // Masing: the shift at -Q* is minus the one at +Q*, and back at +Q* it is again.
  const double d = steps[1]["tangential_shift"].get<double>();
  CHECK(steps[3]["tangential_shift"].get<double>() == Approx(-d).epsilon(1e-3));
  CHECK(steps[5]["tangential_shift"].get<double>() == Approx(d).epsilon(1e-3));
  // One closed loop, from step 2 (+Q*) through step 4 (-Q*) back at step 6; its energy the
  // friction work in between, and Mindlin-Deresiewicz's (Johnson 1985 eq. 7.59) within 8 % at
  // a/dx = 8: measured 0.938, 0.990 and 0.987 of it at a/dx = 8, 16 and 32 (the finer grids in
  // tests/test_partial_slip_grid.cpp, slow).
  const nlohmann::json& loops = s["fretting"]["loops"];
  REQUIRE(loops.size() == 1);
  CHECK(loops[0]["from_step"] == 2);
  CHECK(loops[0]["to_step"] == 6);
  CHECK(loops[0]["amplitude"].get<double>() == Approx(3.0));
  const double work =
      steps[5]["dissipated_energy"].get<double>() - steps[1]["dissipated_energy"].get<double>();
  CHECK(loops[0]["energy"].get<double>() == Approx(work).epsilon(1e-12));
  CHECK(work == Approx(reference().loop_energy(3.0)).epsilon(0.08));
}

TEST_CASE("tangential_shift: the shift control reaches the load control's state",
          "[cli_partial_slip]") {
  const nlohmann::json by_load = read_summary(run_scene_ok(kSlip, "slip_by_load"));
  const double shift = by_load["partial_slip"]["tangential_shift"].get<double>();
  std::ostringstream value;
  value.precision(17);
  value << "tangential_shift = " << shift;
  const nlohmann::json by_shift =
      read_summary(run_scene_ok(kSlip, "slip_by_shift", "tangential_load = 3.0", value.str()));
  CHECK(by_shift["partial_slip"]["converged"] == true);
  CHECK(by_shift["partial_slip"]["tangential_load"].get<double>() == Approx(3.0).epsilon(1e-5));
}

TEST_CASE("tangential_load: what a scene may not ask", "[cli_partial_slip]") {
  const std::string q = "tangential_load = 3.0";
  for (const BadCase& c :
       {BadCase{"slip_full", q, "tangential_load = 6.0", "reaches full sliding"},
        BadCase{"slip_beyond", q, "tangential_load = [1.0, -7.0]", "reaches full sliding"},
        BadCase{"slip_no_friction", "friction = 0.3", "friction = 0.0", "needs friction"},
        BadCase{"slip_empty", q, "tangential_load = []", "lists 0 values"},
        BadCase{"slip_both", q, q + "\ntangential_shift = 1e-6", "not both"},
        BadCase{"slip_sweep", "load = 20.0", "load = [10.0, 20.0]", "not a sweep"},
        BadCase{"slip_frictionless", "nu = 0.4999",
                "nu = 0.4999\n[[coating]]\nmaterial = \"titanium_nitride\"\nthickness = 1e-4\n"
                "interface = \"frictionless\"",
                "frictionless interface"}})
    check_refused(kSlip, c);
  // [output] fields names the partial slip's files like any other; a scene without one has none.
  const fs::path listed =
      run_scene_ok(kSlip + "[output]\nfields = [\"stick\", \"summary\"]\n", "slip_listed");
  CHECK(fs::exists(listed / "stick.npy"));
  CHECK_FALSE(fs::exists(listed / "shear_x.npy"));
  std::string frictionless = kSlip;
  frictionless.replace(frictionless.find("friction = 0.3\ntangential_load = 3.0\n"),
                       std::string("friction = 0.3\ntangential_load = 3.0\n").size(),
                       "[output]\nfields = [\"shear\"]\n");
  check_refused(frictionless, {"slip_output_only", "", "", "needs a partial slip"});
}

TEST_CASE("tangential_load with an [frf] table is refused", "[cli_partial_slip]") {
  const std::string table = std::string(COATFFT_SOURCE_DIR) + "/examples/scenes/tabulated_frf.csv";
  // The body of kSlip given as a table (tabulated_frf.toml's, another body: refused first).
  const std::string scene =
      std::string(kSlip).replace(kSlip.find("[substrate]"), 0, "[frf]\npath = \"" + table + "\"\n");
  check_refused(scene, {"slip_frf", "", "", "[frf] table"});
}

TEST_CASE("a fretting step that does not converge is named, its output written, exit 3",
          "[cli_partial_slip]") {
  const fs::path out = scratch("slip_nc_out");
  fs::remove_all(out);
  const auto result = run_coatfft("run " +
                                  write_scene(kSlip, "slip_nc", "tangential_load = 3.0",
                                              "tangential_load = [1.5, 3.0]\nmax_iterations = 2")
                                      .string() +
                                  " -o " + out.string());
  INFO(result.stderr_text);
  CHECK(result.status == 3);
  CHECK(result.stderr_text.find("partial slip: step 1 of 2 (tangential_load = 1.5) did not "
                                "converge") != std::string::npos);
  const nlohmann::json s = read_summary(out);
  CHECK(s["converged"] == false);
  CHECK(s["partial_slip"]["converged"] == false);
  CHECK(s["fretting"]["steps"][0]["converged"] == false);
  CHECK(npy_shape(out / "shear_x.npy") == "(2, 41, 41)");
  CHECK(lines_of(out / "fretting.csv").size() == 3);
}

TEST_CASE("tangential_shift under approach control with an elastic ball, and its stresses",
          "[cli_partial_slip]") {
  // A steel ball on steel pressed by an approach: the couplings cancel (one normal solve), the
  // shift path back and forth. [stress] takes the last step's tractions.
  std::string scene = kSlip;
  scene.replace(scene.find("E = 2e9\nnu = 0.4999"), std::string("E = 2e9\nnu = 0.4999").size(),
                "material = \"steel\"");
  scene.replace(scene.find("load = 20.0"), std::string("load = 20.0").size(),
                "approach = 1.5e-6\nindenter_material = \"steel\"");
  scene.replace(scene.find("tangential_load = 3.0"), std::string("tangential_load = 3.0").size(),
                "tangential_shift = [2e-8, 4e-8, 0.0]");
  const fs::path out = run_scene_ok(scene + "[stress]\ndepths = [5e-5]\n", "slip_shift_stress");
  const nlohmann::json s = read_summary(out);
  CHECK(s["converged"] == true);
  const nlohmann::json& steps = s["fretting"]["steps"];
  REQUIRE(steps.size() == 3);
  CHECK(steps[1]["tangential_shift"].get<double>() == 4e-8);
  CHECK(steps[1]["tangential_load"].get<double>() > steps[0]["tangential_load"].get<double>());
  // Back at zero shift the hysteresis leaves a load against the motion.
  CHECK(steps[2]["tangential_load"].get<double>() < 0.0);
  CHECK(s["partial_slip"]["coupling_solves"] == 1);
  CHECK(s["stress"]["tangential"] == true);
  CHECK(npy_shape(out / "von_mises.npy") == "(1, 41, 41)");
  double total = 0.0;
  const double cell = std::pow(1.9902e-3 / 41, 2);
  const std::vector<double> shear = npy_values(out / "shear_x.npy");
  for (std::size_t k = 2 * 41 * 41; k < shear.size(); ++k) total += shear[k] * cell;
  CHECK(total == Approx(steps[2]["tangential_load"].get<double>()).epsilon(1e-9));
}
