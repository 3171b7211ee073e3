// [method] name = "auto" through the command line (scene/automatic_method.hpp, docs/auto.md): the
// default method, its report in summary.json and `coatfft check`, reductions, refusals, and named
// methods kept as they were.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

nlohmann::json run_summary(const std::string& name, const std::string& scene_text) {
  const fs::path scene = write_scene(scene_text, name, "", "");
  const fs::path out = scratch(name + "_out");
  fs::remove_all(out);
  const ProcessResult r = run_coatfft("run " + scene.string() + " -o " + out.string());
  INFO(r.stderr_text);
  REQUIRE(r.status == 0);
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

// kGoodScene without its [method] section, with `extra` appended.
std::string scene_without_method(const std::string& extra) {
  std::string text = kGoodScene;
  text.erase(text.find("[method]"));
  return text + extra;
}

std::string write_scene_text(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

const std::string soft_coating = "[[coating]]\nE = 21e9\nnu = 0.3\nthickness = 1e-4\n";

}  // namespace

TEST_CASE("a scene without [method] runs auto: Love's coefficients on a homogeneous body",
          "[cli][auto]") {
  // 33^2 cells in a fresh process: direct summation (1.2e6 products, ~0.6 ms) beats DC-FFT,
  // whose first FFTW plan alone costs ~8 ms (model/cost_model.hpp, fftw_start_seconds).
  const nlohmann::json s = run_summary("auto_homogeneous", scene_without_method(""));
  CHECK(s["method"] == "direct");
  CHECK(s["method_requested"] == "auto");
  REQUIRE(s.contains("auto"));
  CHECK(s["auto"]["tolerance"] == 1e-4);
  CHECK(s["auto"]["method"] == "direct");
  CHECK(s["auto"]["candidates"].size() == 5);
  CHECK(s["auto"]["reduction"]["kind"] == "none");
  CHECK(s["predicted_error"].get<double>() <= 1e-4);
  // On 128^2 cells the FFT pays: Love's DC-FFT.
  const nlohmann::json big = run_summary(
      "auto_homogeneous_128",
      write_scene_text(scene_without_method(""), "nx = 33\nny = 33", "nx = 128\nny = 128"));
  CHECK(big["method"] == "dcfft");
  CHECK(!s["auto"]["why"].get<std::string>().empty());
}

TEST_CASE("a coated scene without [method] runs frf-split within the tolerance", "[cli][auto]") {
  const nlohmann::json s = run_summary(
      "auto_coated", scene_without_method(soft_coating + "[method]\ntolerance = 1e-3\n"));
  CHECK(s["method"] == "frf-split");
  CHECK(s["auto"]["split_tolerance"] == 1e-3);
  CHECK(s["auto"]["predicted_error"].get<double>() <= 1e-3);
  // The same scene by frf-split at its default kernel tolerance: the results agree within the
  // tolerance (max |u| ~ uz_max).
  const nlohmann::json named = run_summary(
      "auto_coated_named", scene_without_method(soft_coating + "[method]\nname = \"frf-split\"\n"));
  CHECK(named["method_requested"] == "frf-split");
  CHECK_FALSE(named.contains("auto"));
  CHECK(std::abs(s["uz_max"].get<double>() - named["uz_max"].get<double>()) <=
        1e-3 * named["uz_max"].get<double>());
}

TEST_CASE("auto reduces a coating whose effect is below the tolerance", "[cli][auto]") {
  const std::string thin = "[[coating]]\nE = 400e9\nnu = 0.25\nthickness = 2e-7\n";
  const nlohmann::json s =
      run_summary("auto_thin", scene_without_method(thin + "[method]\ntolerance = 1e-3\n"));
  CHECK(s["auto"]["reduction"]["kind"] == "substrate");
  CHECK((s["method"] == "dcfft" || s["method"] == "direct"));  // Love's: the body is homogeneous
  CHECK(s["auto"]["reduction"]["estimated_effect"].get<double>() <= 0.9e-3);
  const nlohmann::json strict =
      run_summary("auto_thin_strict", scene_without_method(thin + "[method]\ntolerance = 1e-5\n"));
  CHECK(strict["auto"]["reduction"]["kind"] == "none");
  CHECK(strict["method"] == "frf-split");
}

TEST_CASE("auto's keys are refused where they do not apply", "[cli][auto]") {
  const std::string base = scene_without_method("[method]\nname = \"auto\"\n");
  check_refused(base, {"auto_alpha", "name = \"auto\"\n", "name = \"auto\"\nalpha = 4\n",
                       "(which chooses them)"});
  check_refused(base, {"auto_tol_zero", "name = \"auto\"\n", "name = \"auto\"\ntolerance = 0\n",
                       "[method] tolerance"});
  check_refused(base, {"auto_tol_named", "name = \"auto\"\n",
                       "name = \"dcfft\"\ntolerance = 1e-3\n", "applies only to name = \"auto\""});
  check_refused(base, {"auto_bad_name", "name = \"auto\"\n", "name = \"fast\"\n", "\"auto\""});
}

TEST_CASE("coatfft check prints auto's choice, sizes, memory and time", "[cli][auto]") {
  const fs::path scene = write_scene(scene_without_method(soft_coating), "auto_check", "", "");
  const fs::path json = scratch("auto_check.json");
  const std::string command = std::string(COATFFT_EXE) + " check " + scene.string() + " > " +
                              json.string() + " 2>/dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream in(json);
  const nlohmann::json c = nlohmann::json::parse(in);
  CHECK(c["method"] == "frf-split");
  CHECK(c["method_requested"] == "auto");
  CHECK(c["auto"]["why"].get<std::string>().rfind("frf-split", 0) == 0);
  CHECK(c["estimated_seconds"]["total"].get<double>() > 0);
  CHECK(c["estimated_memory_bytes"].get<double>() > 0);
}

// `coatfft check SCENE`'s JSON.
nlohmann::json check_json(const std::string& name, const std::string& scene_text) {
  const fs::path scene = write_scene(scene_text, name, "", "");
  const fs::path json = scratch(name + ".json");
  const std::string command = std::string(COATFFT_EXE) + " check " + scene.string() + " > " +
                              json.string() + " 2>/dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream in(json);
  return nlohmann::json::parse(in);
}

TEST_CASE("coatfft check reduces a coating far below the load's scale without quadrature",
          "[cli][auto]") {
  // 1 pm of TiN under a 1 mm Hertz load: the closed-form bound decides (docs/auto.md, section 2),
  // where the Hankel reference of the accurate bound would need about 1e10 panels.
  const std::string thin = "[[coating]]\nE = 400e9\nnu = 0.25\nthickness = 1e-12\n";
  const nlohmann::json c = check_json("auto_check_1pm", scene_without_method(thin));
  CHECK(c["auto"]["reduction"]["kind"] == "substrate");
  CHECK(c["auto"]["reduction"]["work"]["quadratures"] == 0);
  CHECK(c["auto"]["reduction"]["work"]["frf_evaluations"].get<long>() <= 4001);
  CHECK(c["auto"]["reduction"]["estimated_effect"].get<double>() <= 0.9e-4);
  CHECK((c["method"] == "dcfft" || c["method"] == "direct"));
  // 1e-20 m: the same, where the Hankel reference failed in its quadrature.
  const std::string thinner = "[[coating]]\nE = 400e9\nnu = 0.25\nthickness = 1e-20\n";
  const nlohmann::json d = check_json("auto_check_1e-20", scene_without_method(thinner));
  CHECK(d["auto"]["reduction"]["kind"] == "substrate");
  CHECK(d["auto"]["reduction"]["work"]["quadratures"] == 0);
}

TEST_CASE("coatfft run on a coating far below the load's scale ends, without a Hankel reference",
          "[cli][auto]") {
  // The a-posteriori check's reference would take about 1e10 panels: it is reported as skipped.
  const std::string thin = "[[coating]]\nE = 400e9\nnu = 0.25\nthickness = 1e-12\n";
  const nlohmann::json s = run_summary("auto_run_1pm", scene_without_method(thin));
  CHECK(s["auto"]["reduction"]["kind"] == "substrate");
  CHECK(s["a_posteriori"]["error"].is_null());
  CHECK(s["a_posteriori"]["measure"].get<std::string>().find("far thinner than the load") !=
        std::string::npos);
}

TEST_CASE("a load radius beyond half the domain is refused by run and check", "[cli][auto]") {
  // 200 m on a 3 mm domain (metres for micrometres): refused by the grid's one check of a load
  // radius (require_load_radius, which Python's make_operator load_radius also goes through).
  const std::string base = scene_without_method("");
  check_refused(base, {"auto_radius_200", "a = 1.0e-3", "a = 200",
                       "= 200 m must be finite and > 0, and at most half the domain"});
  const fs::path scene = write_scene(base, "auto_radius_200_check", "a = 1.0e-3", "a = 200");
  const ProcessResult r = run_coatfft("check " + scene.string());
  CHECK(r.status == 2);
  CHECK(r.stderr_text.find("at most half the domain") != std::string::npos);
}

TEST_CASE("[grid] refine = \"auto\" chooses the grid for tolerance_total", "[cli][auto]") {
  const std::string refined = R"([grid]
lx = 3.0e-3
ly = 3.0e-3
refine = "auto"
tolerance_total = 1e-2
[substrate]
material = "steel"
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
sampling = "cell_average"
)";
  const nlohmann::json s = run_summary("refine_auto", refined);
  REQUIRE(!s["refinement"].is_null());
  CHECK(s["refinement"]["tolerance_total"] == 1e-2);
  CHECK(s["refinement"]["operator_tolerance"] == 1e-3);  // a tenth by default
  CHECK(s["nx"] == s["ny"]);
  CHECK(s["nx"].get<int>() >= 8);
  // The run's own estimate on the chosen grid meets the load's share, and the true error
  // against Hertz's closed form (Johnson 1985) is within the total.
  CHECK(s["load_discretization"]["estimated_error"].get<double>() <= 0.9e-2);
  CHECK(s["max_error_vs_hertz"].get<double>() <= 1e-2);
  CHECK(s["a_posteriori"]["error"].get<double>() <= 1e-2);
  const std::string grid = "refine = \"auto\"\ntolerance_total = 1e-2\n";
  check_refused(refined, {"refine_nx", grid, grid + "nx = 64\n", "chooses nx and ny"});
  check_refused(refined, {"refine_named", "sampling = \"cell_average\"\n",
                          "sampling = \"cell_average\"\n[method]\nname = \"dcfft\"\n",
                          "needs [method] name = \"auto\""});
  check_refused(refined, {"refine_tol", "tolerance_total = 1e-2", "tolerance_total = 0.5",
                          "tolerance_total"});
  // A centre-sampled disk converges like dx: 1e-3 would need ~5000 cells a side, over the
  // limit of 1024; refused at once (from the coarse grids' fit), not after minutes.
  std::string disk = refined;
  disk.replace(disk.find("tolerance_total = 1e-2"), 22, "tolerance_total = 1e-3");
  disk.replace(disk.find("kind = \"hertz\"\np0"), 18, "kind = \"uniform_disk\"\np");
  disk.replace(disk.find("\"cell_average\""), 14, "\"centre\"");
  check_refused(disk, {"refine_out_of_reach", "", "", "out of reach"});
  check_refused(kGoodScene,
                {"refine_without", "lx = 3.0e-3\n", "lx = 3.0e-3\ntolerance_total = 1e-2\n",
                 "applies only with refine = \"auto\""});
}

TEST_CASE("summary.json reports the load's discretisation error and an a-posteriori check",
          "[cli][auto]") {
  const nlohmann::json s = run_summary("auto_load_error", kGoodScene);
  // 33^2 cells, centre sampling, a = 1 mm on 3 mm: the estimate bounds the true error against
  // Hertz's closed form within 1 to 3 times (docs/theory.md 4.7).
  const double estimate = s["load_discretization"]["estimated_error"].get<double>();
  const double truth = s["max_error_vs_hertz"].get<double>();
  CHECK(estimate >= truth);
  CHECK(estimate <= 3 * truth);
  CHECK(s["load_discretization"]["sampling"] == "centre");
  CHECK(s["a_posteriori"]["error"].get<double>() <= truth);
  CHECK(s["refinement"].is_null());
}
