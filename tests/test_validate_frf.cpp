// A body given as a table of its FRF ([frf], scene/frf_table_file.hpp) and `coatfft validate-frf`:
// coatfft's own FRFs written as tables pass, tables with the errors a user's FRF could carry
// fail naming the check, a table body runs like the stack it tabulates, and bad tables and
// scenes are refused with one line. The fixture tables are written here, into a scratch folder.
// The checks' library form, validate_frf, passes and fails FRFs that are not tables alike.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/grid.hpp"
#include "frf/frf.hpp"
#include "io/npy.hpp"
#include "layers/layer_stack.hpp"
#include "materials/catalog.hpp"
#include "scene/frf_validation.hpp"
#include "tests/cli_process.hpp"

namespace fs = std::filesystem;

using coatfft::Interface;
using coatfft::LayerStack;
using coatfft::Material;
using coatfft::material_by_name;
using namespace coatfft_test;

namespace {

// The density of the tables that must pass: 80 points per decade interpolate coatfft's layered
// FRFs to <= 2.0e-7 (tests/test_tabulated_frf.cpp), five times below validate-frf's default 1e-6.
constexpr int per_decade = 80;

struct Captured {
  int status;
  std::string out, err;
};

std::string file_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Captured run_captured(const std::string& args) {
  const std::string tag = std::to_string(std::hash<std::string>{}(args));
  const fs::path out = scratch("vfrf_stdout_" + tag), err = scratch("vfrf_stderr_" + tag);
  const std::string command =
      std::string(COATFFT_EXE) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, file_text(out), file_text(err)};
}

// A table of H(k) at per_decade points per decade over k h = 1e-9 .. 1e3, 17 digits.
fs::path write_table(const std::string& name, const std::function<double(double)>& H, double h) {
  const fs::path path = scratch(name + ".csv");
  std::ofstream out(path);
  out << "k,H\n" << std::setprecision(17);
  for (int i = 0; i <= 12 * per_decade; ++i) {
    const double k = 1e-9 / h * std::pow(10.0, static_cast<double>(i) / per_decade);
    out << k << ',' << H(k) << '\n';
  }
  return path;
}

// coatfft's FRF of `stack` (k h over the total thickness, or h = 0.1 mm for a half-space).
fs::path write_table(const std::string& name, const LayerStack& stack) {
  const auto frf = coatfft::make_frf(stack);
  const double h = stack.is_homogeneous() ? 1e-4 : stack.total_thickness();
  return write_table(
      name, [&](double k) { return (*frf)(k); }, h);
}

// A scene whose [frf] is NAME.csv (beside it) and whose body sections are `body`.
fs::path write_table_scene(const std::string& name, const std::string& body,
                           const std::string& frf_keys = "") {
  const fs::path path = scratch(name + ".toml");
  std::ofstream(path) << "[grid]\nnx = 33\nny = 33\nlx = 3.0e-3\nly = 3.0e-3\n"
                      << "[frf]\npath = \"" << name << ".csv\"\n"
                      << frf_keys << body
                      << "[pressure]\nkind = \"hertz\"\np0 = 1.0e9\na = 1.0e-3\n"
                      << "[method]\nname = \"frf-split\"\n";
  return path;
}

const std::string steel_body = "[substrate]\nmaterial = \"steel\"\n";
const std::string coated_body = steel_body +
                                "[[coating]]\nmaterial = \"titanium_nitride\"\n"
                                "thickness = 1.0e-4\n";
const std::string multilayer_body = steel_body +
                                    "[[coating]]\nmaterial = \"titanium_nitride\"\n"
                                    "thickness = 3.0e-5\n"
                                    "[[coating]]\nmaterial = \"peek\"\nthickness = 5.0e-5\n"
                                    "interface = \"frictionless\"\n"
                                    "[[coating]]\nmaterial = \"alumina\"\nthickness = 2.0e-5\n";

LayerStack coated_stack() {
  return LayerStack({{material_by_name("titanium_nitride"), 1e-4, Interface::bonded}},
                    material_by_name("steel"));
}

// H of the bonded coating by (C1) of docs/frf.md with the sign of the numerator's 4 beta t X term
// flipped: what a transcription error in the formula gives. It leaves both limits (t -> 0 and
// t -> inf) as they are and changes H where t X is not small, about 1e-2 < k h < 10.
double flipped_bonded_H(const Material& coating, const Material& substrate, double h, double k) {
  const double m = coating.shear_modulus() / substrate.shear_modulus();
  const double k1 = coating.kolosov(), k2 = substrate.kolosov();
  const double alpha = (m * k2 - k1) / (m * k2 + 1.0);
  const double beta = (m - 1.0) / (m + k1);
  const double t = k * h, X = std::exp(-2.0 * t);
  const double C = (1.0 - 4.0 * beta * t * X - alpha * beta * X * X) /
                   (1.0 - (alpha + beta + 4.0 * beta * t * t) * X + alpha * beta * X * X);
  return 2.0 * C / (coating.plane_strain_modulus() * k);
}

std::string seventeen_digits(double value) {
  std::ostringstream os;
  os << std::setprecision(17) << value;
  return os.str();
}

}  // namespace

TEST_CASE("validate-frf passes coatfft's own FRFs written as tables", "[cli][validate_frf]") {
  const Material steel = material_by_name("steel");
  struct Case {
    const char* name;
    std::string body;
    LayerStack stack;
    bool give_limits;
  };
  const LayerStack multilayer({{material_by_name("titanium_nitride"), 3e-5, Interface::bonded},
                               {material_by_name("peek"), 5e-5, Interface::frictionless},
                               {material_by_name("alumina"), 2e-5, Interface::bonded}},
                              steel);
  for (const Case& c : {Case{"vfrf_homogeneous", steel_body, LayerStack(steel), false},
                        Case{"vfrf_coated", coated_body, coated_stack(), false},
                        Case{"vfrf_multilayer", multilayer_body, multilayer, true}}) {
    INFO(c.name);
    write_table(c.name, c.stack);
    const auto frf = coatfft::make_frf(c.stack);
    const std::string limits = c.give_limits
                                   ? "c0 = " + seventeen_digits(frf->c0()) +
                                         "\nc_inf = " + seventeen_digits(frf->c_inf()) + "\n"
                                   : "";
    const auto result =
        run_captured("validate-frf " + write_table_scene(c.name, c.body, limits).string());
    INFO(result.out << result.err);
    CHECK(result.status == 0);
    CHECK(result.out.find("all 8 checks within tolerance") != std::string::npos);
    CHECK(result.out.find("FAILED") == std::string::npos);
  }
}

TEST_CASE("validate-frf catches wrong tables, naming the check", "[cli][validate_frf]") {
  const LayerStack stack = coated_stack();
  const auto exact = coatfft::make_frf(stack);
  const double h = 1e-4;
  const auto failing = [](const fs::path& scene) {
    const auto result = run_captured("validate-frf " + scene.string());
    INFO(result.out << result.err);
    CHECK(result.status == 1);
    return result;
  };
  SECTION("off by 1e-3 over one decade of k") {
    write_table(
        "vfrf_off",
        [&](double k) { return (*exact)(k) * (k * h >= 0.1 && k * h <= 1 ? 1.001 : 1); }, h);
    const auto result = failing(write_table_scene("vfrf_off", coated_body));
    CHECK(result.err.find("FAILED: frf_at_points, frf_between_points") != std::string::npos);
  }
  SECTION("a wrong c0") {
    write_table("vfrf_c0", stack);
    const auto result = failing(write_table_scene(
        "vfrf_c0", coated_body, "c0 = " + seventeen_digits(1.001 * exact->c0()) + "\n"));
    CHECK(result.err.find("FAILED: c0") != std::string::npos);
  }
  SECTION("a sign error in one term of the coated formula") {
    const Material tin = material_by_name("titanium_nitride"), steel = material_by_name("steel");
    write_table(
        "vfrf_sign", [&](double k) { return flipped_bonded_H(tin, steel, h, k); }, h);
    const auto result = failing(write_table_scene("vfrf_sign", coated_body));
    for (const char* check : {"frf_at_points", "hertz_frf_split", "uniform_disk_hankel"})
      CHECK(result.err.find(check) != std::string::npos);
    // The limits are right: the error lies in between.
    CHECK(result.err.find(": c0") == std::string::npos);
  }
}

TEST_CASE("coatfft run on a table body reports it and matches the stack", "[cli][validate_frf]") {
  write_table("vfrf_run", coated_stack());
  const fs::path table_out = scratch("vfrf_run_out"), stack_out = scratch("vfrf_stack_out");
  fs::remove_all(table_out);
  fs::remove_all(stack_out);
  const fs::path scene = write_table_scene("vfrf_run", coated_body);
  auto result = run_coatfft("run " + scene.string() + " -o " + table_out.string());
  INFO(result.stderr_text);
  REQUIRE(result.status == 0);
  // The same scene without [frf]: the operator of the stack itself.
  std::string text = file_text(scene);
  text.erase(text.find("[frf]"), text.find("[substrate]") - text.find("[frf]"));
  std::ofstream(scratch("vfrf_stack.toml")) << text;
  result = run_coatfft("run " + scratch("vfrf_stack.toml").string() + " -o " + stack_out.string());
  REQUIRE(result.status == 0);

  nlohmann::json summary;
  std::ifstream(table_out / "summary.json") >> summary;
  CHECK(summary["frf"] == "table");
  const auto& table = summary["frf_table"];
  CHECK(table["points"] == 12 * per_decade + 1);
  CHECK(table["c0_estimated"] == true);
  CHECK(table["c_inf_estimated"] == true);
  CHECK(fs::path(table["path"].get<std::string>()).filename() == "vfrf_run.csv");
  CHECK(table["c0"].get<double>() == Approx(coatfft::make_frf(coated_stack())->c0()).epsilon(1e-8));
  // The table interpolates H to <= 2.0e-7 (6e-9 for this body), and frf-split is linear in H:
  // the displacements agree to validate-frf's default tolerance, 1e-6.
  const coatfft::Field u_table = coatfft::io::read_npy(table_out / "uz.npy");
  const coatfft::Field u_stack = coatfft::io::read_npy(stack_out / "uz.npy");
  CHECK((u_table - u_stack).abs().maxCoeff() <= 1e-6 * u_stack.abs().maxCoeff());
}

TEST_CASE("the table coatfft frf writes is read back as an [frf] table", "[cli][validate_frf]") {
  // The coated stack's scene, tabulated by `coatfft frf` (columns k,kh_total,frf,
  // frf_over_substrate) over k h = 1e-9 .. 1e3 at per_decade points per decade, flat enough at
  // both ends for c0 and c_inf to be estimated, then given back as the [frf] of the same scene.
  const fs::path stack_scene = write_table_scene("vfrf_roundtrip_stack", coated_body);
  std::string text = file_text(stack_scene);
  text.erase(text.find("[frf]"), text.find("[substrate]") - text.find("[frf]"));
  std::ofstream(stack_scene) << text;
  const fs::path table = scratch("vfrf_roundtrip.csv");
  fs::remove(table);
  const double h = coated_stack().total_thickness();
  auto result = run_captured("frf " + stack_scene.string() + " -o " + table.string() + " --k-min " +
                             seventeen_digits(1e-9 / h) + " --k-max " + seventeen_digits(1e3 / h) +
                             " --points " + std::to_string(12 * per_decade + 1));
  INFO(result.err);
  REQUIRE(result.status == 0);
  REQUIRE(file_text(table).rfind("k,kh_total,frf,frf_over_substrate\n", 0) == 0);

  const fs::path table_scene = write_table_scene("vfrf_roundtrip", coated_body);
  const fs::path table_out = scratch("vfrf_roundtrip_out"), stack_out = scratch("vfrf_rt_out");
  fs::remove_all(table_out);
  fs::remove_all(stack_out);
  result = run_captured("run " + table_scene.string() + " -o " + table_out.string());
  INFO(result.err);
  REQUIRE(result.status == 0);
  REQUIRE(run_captured("run " + stack_scene.string() + " -o " + stack_out.string()).status == 0);
  nlohmann::json summary;
  std::ifstream(table_out / "summary.json") >> summary;
  CHECK(summary["frf"] == "table");
  CHECK(summary["frf_table"]["points"] == 12 * per_decade + 1);
  // As for a table written here: 80 points per decade interpolate H to <= 2e-7, and frf-split
  // is linear in H, so the displacements agree to validate-frf's default tolerance, 1e-6.
  const coatfft::Field u_table = coatfft::io::read_npy(table_out / "uz.npy");
  const coatfft::Field u_stack = coatfft::io::read_npy(stack_out / "uz.npy");
  CHECK((u_table - u_stack).abs().maxCoeff() <= 1e-6 * u_stack.abs().maxCoeff());
}

TEST_CASE("bad FRF tables and [frf] scenes are refused with exit 2, one line, no output",
          "[cli][validate_frf][bad_input]") {
  const auto table_with = [](const std::string& name, const std::string& text) {
    std::ofstream(scratch(name + ".csv")) << text;
  };
  const std::string rows = "1e2,2e-11\n1e3,2e-12\n1e4,2e-13\n1e5,2e-14\n1e6,2e-15\n";
  table_with("vfrf_good", "k,H\n" + rows);
  const std::string base = file_text(write_table_scene("vfrf_good", steel_body, ""));
  struct BadTable {
    const char* name;
    std::string text;
    const char* must_mention;
  };
  for (const BadTable& t : {
           BadTable{"vfrf_descending",
                    "k,H\n1e2,2e-11\n1e3,2e-12\n1e1,2e-13\n1e5,2e-14\n1e6,1e-15\n",
                    "vfrf_descending.csv:4: row 2: k = 10 rad/m is not above"},
           BadTable{"vfrf_negative", "k,H\n1e2,2e-11\n1e3,-2e-12\n" + rows.substr(20),
                    "vfrf_negative.csv:3: row 1: H = -2e-12"},
           BadTable{"vfrf_nan", "# comment\nk,H\n1e2,nan\n" + rows.substr(10),
                    "vfrf_nan.csv:3: row 0: H = nan"},
           BadTable{"vfrf_few", "k,H\n1e2,2e-11\n1e3,2e-12\n", "2 rows"},
           BadTable{"vfrf_no_header", rows, "vfrf_no_header.csv:1: the header names no column k"},
           BadTable{"vfrf_no_H", "k,note\n" + rows,
                    "vfrf_no_H.csv:1: the header names no column H"},
           BadTable{"vfrf_H_and_frf", "k,H,frf\n" + rows, "column frf is named twice"},
           BadTable{"vfrf_short_row", "k,kh,H\n" + rows,
                    "vfrf_short_row.csv:2: row 0 has 2 values"},
           BadTable{"vfrf_word", "H,k\n2e-11,1e2\nabc,1e3\n", "vfrf_word.csv:3: row 1, column 0"},
           BadTable{"vfrf_not_flat",
                    "k,H\n1e2,2e-11\n1e3,2.1e-12\n1e4,2e-13\n1e5,2e-14\n1e6,2e-15\n",
                    "small-k limit"},
       }) {
    table_with(t.name, t.text);
    check_refused(base,
                  BadCase{t.name, "vfrf_good.csv", std::string(t.name) + ".csv", t.must_mention});
  }
  const std::array scene_cases{
      BadCase{"vfrf_love", "name = \"frf-split\"", "name = \"dcfft\"", "Love's coefficients"},
      BadCase{"vfrf_bad_c0", "[frf]\n", "[frf]\nc0 = -1.0\n", "[frf] c0"},
      BadCase{"vfrf_unknown_key", "[frf]\n", "[frf]\nc_zero = 1.0\n", "c_zero"},
      BadCase{"vfrf_missing_file", "vfrf_good.csv", "nowhere.csv", "nowhere.csv"},
      BadCase{"vfrf_elastic_indenter", "[pressure]\nkind = \"hertz\"\np0 = 1.0e9\na = 1.0e-3\n",
              "[contact]\nindenter = \"sphere\"\nradius = 0.01\nload = 1.0\n"
              "indenter_material = \"steel\"\n",
              "table body ([frf])"},
  };
  for (const BadCase& c : scene_cases) check_refused(base, c);
}

TEST_CASE("[frf] c0 and c_inf that contradict the table's ends are refused, or warned about",
          "[cli][validate_frf][bad_input]") {
  // k H = 2e-9 1/Pa at every row: its ends are both limits.
  std::ofstream(scratch("vfrf_limits.csv"))
      << "k,H\n1e2,2e-11\n1e3,2e-12\n1e4,2e-13\n1e5,2e-14\n1e6,2e-15\n";
  const std::string base = file_text(write_table_scene("vfrf_limits", steel_body, ""));
  check_refused(base, BadCase{"vfrf_c0_1e8", "[frf]\n", "[frf]\nc0 = 0.2\n",
                              "TabulatedFrf: c0 = 0.2 1/Pa and the table's k H = "});
  check_refused(base, BadCase{"vfrf_c_inf_1e8", "[frf]\n", "[frf]\nc_inf = 2e-17\n",
                              "differ by a factor 1e+08"});
  // 5 % off: the run goes on, and says so on stderr and in summary.json.
  const fs::path scene = write_scene(base, "vfrf_c0_5pc", "[frf]\n", "[frf]\nc0 = 2.1e-9\n");
  const fs::path out = scratch("vfrf_c0_5pc_out");
  fs::remove_all(out);
  const auto result = run_captured("run " + scene.string() + " -o " + out.string());
  INFO(result.err);
  REQUIRE(result.status == 0);
  CHECK(result.err.find("coatfft: warning: [frf] c0 = 2.1e-09 1/Pa") != std::string::npos);
  const nlohmann::json summary = read_summary(out);
  REQUIRE(summary["warnings"].size() == 1);
  CHECK(summary["warnings"][0].get<std::string>().find("differ by 5") != std::string::npos);
}

TEST_CASE("validate-frf refuses what it cannot validate", "[cli][validate_frf][bad_input]") {
  write_table("vfrf_alone", LayerStack(material_by_name("steel")));
  // [frf] alone is a body `coatfft run` accepts, but there is nothing to validate it against.
  const fs::path alone = write_table_scene("vfrf_alone", "");
  const fs::path out = scratch("vfrf_alone_out");
  fs::remove_all(out);
  CHECK(run_coatfft("run " + alone.string() + " -o " + out.string()).status == 0);
  auto result = run_captured("validate-frf " + alone.string());
  CHECK(result.status == 2);
  CHECK(result.err.find("nothing to validate the [frf] table against") != std::string::npos);
  result = run_captured("validate-frf " + scene_with("vfrf_no_frf", "", "").string());
  CHECK(result.status == 2);
  CHECK(result.err.find("no [frf] section") != std::string::npos);
  result = run_captured("validate-frf " + alone.string() + " --tolerance 0");
  CHECK(result.status == 2);
  CHECK(result.err.find("--tolerance = 0") != std::string::npos);
}

TEST_CASE("the tabulated-FRF example passes validate-frf and runs", "[cli][validate_frf]") {
  const fs::path dir = fs::path(COATFFT_SOURCE_DIR) / "examples" / "scenes";
  CHECK(fs::file_size(dir / "tabulated_frf.csv") < 100 * 1024);
  auto result = run_captured("validate-frf " + (dir / "tabulated_frf.toml").string());
  INFO(result.out << result.err);
  CHECK(result.status == 0);
  const fs::path out = scratch("vfrf_example_out");
  fs::remove_all(out);
  result = run_captured("run " + (dir / "tabulated_frf.toml").string() + " -o " + out.string());
  CHECK(result.status == 0);
}

// The library form of validate-frf (scene/frf_validation.hpp), on FRFs that are not tables: the
// form the Python module calls with a user's own FRF. A small grid keeps it fast: 0.2 mm, 64
// cells a side, resolves k h = 6e-3 .. 20 of a 2 um coating.
namespace {

LayerStack thin_coated_stack() {
  return LayerStack({{material_by_name("titanium_nitride"), 2e-6, Interface::bonded}},
                    material_by_name("steel"));
}

const coatfft::Grid small_grid(64, 64, 2e-4, 2e-4);

// An FRF that is `exact` times factor(k), with c0 scaled by c0_factor: the errors a user's FRF
// could carry, without a table between.
class DistortedFrf final : public coatfft::Frf {
 public:
  DistortedFrf(const coatfft::Frf& exact, std::function<double(double)> factor, double c0_factor)
      : exact_(exact), factor_(std::move(factor)), c0_factor_(c0_factor) {}
  double operator()(double k) const override { return exact_(k) * factor_(k); }
  double c0() const override { return c0_factor_ * exact_.c0(); }
  double c_inf() const override { return exact_.c_inf(); }
  std::string name() const override { return "distorted"; }

 private:
  const coatfft::Frf& exact_;
  std::function<double(double)> factor_;
  double c0_factor_;
};

std::string failed_checks(const coatfft::scene::FrfValidation& result) {
  std::string failed;
  for (const auto& check : result.checks)
    if (!check.passed) failed += (failed.empty() ? "" : ", ") + check.name;
  return failed;
}

}  // namespace

TEST_CASE("validate_frf passes coatfft's own FRF of the stack, sampled over the grid",
          "[cli][validate_frf]") {
  const LayerStack stack = thin_coated_stack();
  const auto frf = coatfft::make_frf(stack);
  const auto result = coatfft::scene::validate_frf(*frf, stack, small_grid, 1e-6);
  INFO(failed_checks(result));
  CHECK(result.passed);
  CHECK(result.reference == "coatfft's " + frf->name() + " FRF of the stack");
  std::vector<std::string> names;
  for (const auto& check : result.checks) {
    names.push_back(check.name);
    CHECK(check.passed);
    CHECK(check.difference <= check.tolerance);
  }
  CHECK(names == std::vector<std::string>{"c0", "c_inf", "frf_at_points", "frf_between_points",
                                          "hertz_frf_split", "hertz_hankel",
                                          "uniform_disk_frf_split", "uniform_disk_hankel"});
  // Not a table: no given-or-estimated note on the limits, and H is sampled over the
  // wavenumbers the grid resolves (2 pi / (10 L) = 3.1e3 .. 10 pi / dx = 1.0e7 rad/m).
  CHECK(result.checks[0].detail == "k -> 0");
  CHECK(result.checks[1].detail == "k -> inf");
  // A tolerance below what the references resolve is raised to their floors.
  const auto strict = coatfft::scene::validate_frf(*frf, stack, small_grid, 1e-12);
  CHECK(strict.checks[2].tolerance == 1e-12);
  CHECK(strict.checks[4].tolerance == 1e-10);
  CHECK(strict.checks[5].tolerance == 1e-9);
}

TEST_CASE("validate_frf catches a wrong FRF, naming the check", "[cli][validate_frf]") {
  const LayerStack stack = thin_coated_stack();
  const auto exact = coatfft::make_frf(stack);
  const double h = 2e-6;
  SECTION("off by 1e-3 over one decade of k") {
    const DistortedFrf off(
        *exact, [&](double k) { return k * h >= 0.1 && k * h <= 1 ? 1.001 : 1.0; }, 1.0);
    const auto result = coatfft::scene::validate_frf(off, stack, small_grid, 1e-6);
    const std::string failed = failed_checks(result);
    INFO(failed);
    CHECK_FALSE(result.passed);
    CHECK(failed.find("frf_at_points, frf_between_points") == 0);
    CHECK(result.checks[2].difference == Approx(1e-3).epsilon(1e-9));
    // The limits are right: the error lies in between.
    CHECK(result.checks[0].passed);
    CHECK(result.checks[1].passed);
  }
  SECTION("a wrong c0") {
    const DistortedFrf wrong_c0(
        *exact, [](double) { return 1.0; }, 1.001);
    const auto result = coatfft::scene::validate_frf(wrong_c0, stack, small_grid, 1e-6);
    INFO(failed_checks(result));
    CHECK_FALSE(result.passed);
    CHECK(failed_checks(result).find("c0") == 0);
    CHECK(result.checks[0].difference == Approx(1e-3).epsilon(1e-9));
    CHECK(result.checks[2].passed);
  }
}

TEST_CASE("validate_frf refuses a tolerance outside (0, 1) and a load without force",
          "[cli][validate_frf][bad_input]") {
  const LayerStack stack = thin_coated_stack();
  const auto frf = coatfft::make_frf(stack);
  for (const double tolerance : {0.0, 1.0, -1e-6, std::nan("")})
    CHECK_THROWS_AS(coatfft::scene::validate_frf(*frf, stack, small_grid, tolerance),
                    coatfft::InvalidArgument);
  CHECK_THROWS_WITH(coatfft::scene::validate_frf(*frf, stack, small_grid, 0.0),
                    Catch::Matchers::Contains("--tolerance = 0 must be in (0, 1)"));
  coatfft::scene::FrfValidationOptions options;
  options.load = coatfft::scene::FrfCheckLoad{coatfft::AxisymmetricLoad::hertz, 0.0, 5e-5,
                                              coatfft::Sampling::cell_average};
  CHECK_THROWS_AS(coatfft::scene::validate_frf(*frf, stack, small_grid, 1e-6, options),
                  coatfft::InvalidArgument);
  CHECK_THROWS_WITH(coatfft::scene::validate_frf(*frf, stack, small_grid, 1e-6, options),
                    Catch::Matchers::Contains("amplitude = 0"));
}
