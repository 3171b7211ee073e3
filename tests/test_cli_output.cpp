// The [output] section of a scene: `coatfft run` writes the files it names (and summary.json,
// always), byte for byte as a full run writes them, checks and replaces no others, and refuses
// lists it cannot honour with one line and no output. run_scene (scene/scene_run.hpp) computes
// what the run writes, without writing anything.
#include <array>
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/npy.hpp"
#include "scene/scene_run.hpp"
#include "tests/cli_process.hpp"
#include "tests/test_support.hpp"

using namespace coatfft_test;

namespace {

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

std::set<std::string> keys_of(const fs::path& summary_file) {
  nlohmann::json summary;
  std::ifstream(summary_file) >> summary;
  std::set<std::string> keys;
  for (const auto& item : summary.items()) keys.insert(item.key());
  return keys;
}

// `base` with an [output] section listing `fields` (TOML text, e.g. R"(["uz"])"), run into a
// fresh scratch folder NAME_out, which is returned; the run must succeed.
fs::path run_with_fields(const std::string& base, const std::string& name,
                         const std::string& fields) {
  const fs::path scene = write_scene(base + "[output]\nfields = " + fields + "\n", name, "", "");
  const fs::path out = scratch(name + "_out");
  fs::remove_all(out);
  const ProcessResult result = run_coatfft("run " + scene.string() + " -o " + out.string());
  INFO(result.stderr_text);
  REQUIRE(result.status == 0);
  CHECK(result.stderr_text.empty());
  return out;
}

fs::path run_default(const std::string& base, const std::string& name) {
  const fs::path out = scratch(name + "_out");
  fs::remove_all(out);
  REQUIRE(run_coatfft("run " + write_scene(base, name, "", "").string() + " -o " + out.string())
              .status == 0);
  return out;
}

// The scene `base` alone in a fresh folder NAME/, so that anything written beside it shows.
fs::path scene_in_own_folder(const std::string& base, const std::string& name) {
  fs::remove_all(scratch(name));
  fs::create_directories(scratch(name));
  return write_scene(base, name + "/scene", "", "");
}

nlohmann::json json_of(const fs::path& file) {
  nlohmann::json json;
  std::ifstream(file) >> json;
  return json;
}

// Bit for bit: the same computation, not merely close values.
bool same_bits(const coatfft::Field& a, const coatfft::Field& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// `json` without its measured times (keys ending in "_seconds" but not the cost model's
// "predicted_..._seconds"), at any depth: what two runs of one scene share.
nlohmann::json without_timings(const nlohmann::json& json) {
  if (json.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : json) out.push_back(without_timings(item));
    return out;
  }
  if (!json.is_object()) return json;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& item : json.items()) {
    const std::string& key = item.key();
    const bool measured =
        key.size() > 8 && key.ends_with("_seconds") && !key.starts_with("predicted");
    if (!measured) out[key] = without_timings(item.value());
  }
  return out;
}

// std::cerr captured while alive.
class CaptureStderr {
 public:
  CaptureStderr() : old_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CaptureStderr() { std::cerr.rdbuf(old_); }
  CaptureStderr(const CaptureStderr&) = delete;
  CaptureStderr& operator=(const CaptureStderr&) = delete;
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* old_;
};

// run_scene on `base` (in a folder of its own, which must stay as it was, and with nothing
// printed) against `coatfft run` of the same scene: the same fields bit for bit, the same summary
// but for the times. Returns run_scene's result.
coatfft::scene::SceneRun check_run_scene_as_run(const std::string& base, const std::string& name) {
  const fs::path scene = scene_in_own_folder(base, name);
  const auto before = snapshot(scene.parent_path());
  std::optional<coatfft::scene::SceneRun> result;
  std::string printed;
  {
    CaptureStderr captured;
    result.emplace(coatfft::scene::run_scene(scene));
    printed = captured.text();
  }
  CHECK(printed.empty());
  CHECK(snapshot(scene.parent_path()) == before);
  coatfft::scene::SceneRun& run = *result;

  const fs::path out = scratch(name + "_out");
  fs::remove_all(out);
  REQUIRE(run_coatfft("run " + scene.string() + " -o " + out.string()).status == 0);
  CHECK(same_bits(run.uz, coatfft::io::read_npy(out / "uz.npy")));
  CHECK(same_bits(run.pressure, coatfft::io::read_npy(out / "pressure.npy")));
  CHECK(run.gap.has_value() == fs::exists(out / "gap.npy"));
  if (run.gap) CHECK(same_bits(*run.gap, coatfft::io::read_npy(out / "gap.npy")));
  CHECK(keys_of(out / "summary.json") == [&] {
    std::set<std::string> keys;
    for (const auto& item : run.summary.items()) keys.insert(item.key());
    return keys;
  }());
  CHECK(without_timings(run.summary) == without_timings(json_of(out / "summary.json")));
  CHECK(run.grid.nx() == run.summary["nx"].get<long>());
  return std::move(run);
}

}  // namespace

TEST_CASE("[output] fields: only the files named, as a full run writes them", "[cli][output]") {
  const fs::path full = run_default(kGoodScene, "output_full");
  CHECK(names_in(full) == std::set<std::string>{".coatfft-outputs", "uz.npy", "pressure.npy",
                                                "displacement.csv", "summary.json"});

  // summary.json comes without being named.
  const fs::path uz = run_with_fields(kGoodScene, "output_uz", R"(["uz"])");
  CHECK(names_in(uz) == std::set<std::string>{".coatfft-outputs", "uz.npy", "summary.json"});
  CHECK(text_of(uz / ".coatfft-outputs") == "uz.npy\nsummary.json\n");
  CHECK(text_of(uz / "uz.npy") == text_of(full / "uz.npy"));

  // The order of the list does not matter; the manifest keeps the order of a full run.
  const fs::path some =
      run_with_fields(kGoodScene, "output_some", R"(["displacement_csv", "summary", "pressure"])");
  CHECK(names_in(some) == std::set<std::string>{".coatfft-outputs", "pressure.npy",
                                                "displacement.csv", "summary.json"});
  CHECK(text_of(some / ".coatfft-outputs") == "pressure.npy\ndisplacement.csv\nsummary.json\n");
  CHECK(text_of(some / "displacement.csv") == text_of(full / "displacement.csv"));
  CHECK(text_of(some / "pressure.npy") == text_of(full / "pressure.npy"));

  // The summary alone keeps every key of a full run's.
  const fs::path summary = run_with_fields(kGoodScene, "output_summary", R"(["summary"])");
  CHECK(names_in(summary) == std::set<std::string>{".coatfft-outputs", "summary.json"});
  CHECK(keys_of(summary / "summary.json") == keys_of(full / "summary.json"));
}

TEST_CASE("[output] fields of a contact: gap.npy by default and on request", "[cli][output]") {
  const fs::path full = run_default(kSmallContactScene, "output_contact_full");
  CHECK(names_in(full) == std::set<std::string>{".coatfft-outputs", "uz.npy", "pressure.npy",
                                                "displacement.csv", "summary.json", "gap.npy"});
  const fs::path gap = run_with_fields(kSmallContactScene, "output_contact_gap", R"(["gap"])");
  CHECK(names_in(gap) == std::set<std::string>{".coatfft-outputs", "gap.npy", "summary.json"});
  CHECK(text_of(gap / "gap.npy") == text_of(full / "gap.npy"));
  CHECK(keys_of(gap / "summary.json") == keys_of(full / "summary.json"));
}

TEST_CASE("[output] fields: outputs not asked for are neither checked nor kept from a former run",
          "[cli][output]") {
  const fs::path out = run_default(kGoodScene, "output_stale");
  std::ofstream(out / "mine.txt") << "user data";
  const fs::path scene = write_scene(std::string(kGoodScene) + "[output]\nfields = [\"summary\"]\n",
                                     "output_stale_summary", "", "");
  // The former run's uz.npy, pressure.npy and displacement.csv are listed in its manifest and
  // not written now: removed, so that OUTDIR holds what this run computed. The user's file stays.
  REQUIRE(run_coatfft("run " + scene.string() + " -o " + out.string()).status == 0);
  CHECK(names_in(out) == std::set<std::string>{".coatfft-outputs", "summary.json", "mine.txt"});
  CHECK(text_of(out / "mine.txt") == "user data");
  // A folder where uz.npy would go stops a full run, but not a run that does not write uz.npy.
  fs::create_directory(out / "uz.npy");
  const fs::path full = write_scene(kGoodScene, "output_stale_full", "", "");
  CHECK(run_coatfft("run " + full.string() + " -o " + out.string()).status == 2);
  CHECK(run_coatfft("run " + scene.string() + " -o " + out.string()).status == 0);
  CHECK(fs::is_directory(out / "uz.npy"));
}

TEST_CASE("[output] fields that cannot be honoured are refused with the key and the value",
          "[cli][output][bad_input]") {
  const std::string method = "name = \"dcfft\"\n";
  const auto with = [&](const std::string& output) { return method + "[output]\n" + output; };
  const std::array cases{
      BadCase{"output_empty", method, with("fields = []\n"), "[output] fields (line 15) = []"},
      BadCase{"output_unknown", method, with("fields = [\"uz\", \"displacement\"]\n"),
              "\"displacement\" is not one of \"uz\", \"pressure\", \"gap\""},
      BadCase{"output_twice", method, with("fields = [\"uz\", \"pressure\", \"uz\"]\n"),
              "\"uz\" is listed twice"},
      BadCase{"output_summary_twice", method, with("fields = [\"summary\", \"summary\"]\n"),
              "\"summary\" is listed twice"},
      BadCase{"output_gap", method, with("fields = [\"gap\"]\n"),
              "\"gap\" applies only to a [contact] scene"},
      BadCase{"output_string", method, with("fields = \"uz\"\n"),
              "fields (line 15) must be a list of strings, got string"},
      BadCase{"output_number", method, with("fields = [\"uz\", 1]\n"),
              "must be a list of strings, got an entry of type integer"},
      BadCase{"output_key", method, with("field = [\"uz\"]\n"), "[output] unknown key \"field\""},
      BadCase{"output_ux", method, with("fields = [\"uz\", \"ux\"]\n"),
              "\"ux\" needs the in-plane surface response"},
  };
  for (const auto& c : cases) check_refused(kGoodScene, c);
  // coatfft check reads the scene as run does.
  const fs::path scene = write_scene(kGoodScene, "output_check", method, with("fields = []\n"));
  const ProcessResult checked = run_coatfft("check " + scene.string());
  CHECK(checked.status == 2);
  CHECK(checked.stderr_text.find("[output] fields") != std::string::npos);
}

TEST_CASE("run_scene computes what coatfft run writes, and writes nothing", "[cli][output]") {
  SECTION("a known pressure") {
    const coatfft::scene::SceneRun run = check_run_scene_as_run(kGoodScene, "run_scene_pressure");
    CHECK(run.status == coatfft::scene::RunStatus::ok);
    CHECK_FALSE(run.gap);
    CHECK(run.uz.rows() == 33);
  }
  SECTION("a contact, with its gap") {
    const coatfft::scene::SceneRun run =
        check_run_scene_as_run(kSmallContactScene, "run_scene_contact");
    CHECK(run.status == coatfft::scene::RunStatus::ok);
    CHECK(run.gap);
    CHECK(run.summary["converged"] == true);
  }
  SECTION("a run that warns: in the summary only, where the CLI prints it too") {
    const coatfft::scene::SceneRun run =
        check_run_scene_as_run(kPipelineWarningScene, "run_scene_warning");
    REQUIRE(run.summary["warnings"].size() == 1);
    const ProcessResult printed =
        run_coatfft("run " + scratch("run_scene_warning/scene.toml").string() + " -o " +
                    scratch("run_scene_warning_out").string());
    CHECK(printed.stderr_text ==
          "coatfft: warning: " + run.summary["warnings"][0].get<std::string>() + "\n");
  }
}

TEST_CASE("run_scene reads the wisdom file of the scene but never writes it", "[cli][output]") {
  const std::string with_wisdom = std::string(kGoodScene) + "wisdom = \"wisdom.fftw\"\n";
  const fs::path scene = scene_in_own_folder(with_wisdom, "run_scene_wisdom");
  const fs::path wisdom = scene.parent_path() / "wisdom.fftw";
  coatfft::scene::run_scene(scene);
  CHECK_FALSE(fs::exists(wisdom));
  // coatfft run writes it; run_scene then reads it and leaves it as it is.
  const fs::path out = scratch("run_scene_wisdom_out");
  fs::remove_all(out);
  REQUIRE(run_coatfft("run " + scene.string() + " -o " + out.string()).status == 0);
  REQUIRE(fs::exists(wisdom));
  const auto before = snapshot(scene.parent_path());
  const coatfft::scene::SceneRun run = coatfft::scene::run_scene(scene);
  CHECK(snapshot(scene.parent_path()) == before);
  CHECK(same_bits(run.uz, coatfft::io::read_npy(out / "uz.npy")));
}

TEST_CASE("run_scene refuses a bad scene with the message coatfft run prints",
          "[cli][output][bad_input]") {
  const std::array cases{
      BadCase{"run_scene_bad_nx", "nx = 33", "nx = 0", "nx = 0, but nx must be"},
      BadCase{"run_scene_bad_key", "[method]", "[method]\nnmae = \"dcfft\"", "nmae"},
      BadCase{"run_scene_bad_output", "name = \"dcfft\"\n",
              "name = \"dcfft\"\n[output]\nfields = []\n", "[output] fields"},
  };
  for (const BadCase& c : cases) {
    INFO(c.name);
    const fs::path scene = write_scene(kGoodScene, c.name, c.from, c.to);
    const ProcessResult refused = run_coatfft("run " + scene.string() + " -o " +
                                              scratch(std::string(c.name) + "_out").string());
    REQUIRE(refused.status == 2);
    std::string message;
    try {
      coatfft::scene::run_scene(scene);
    } catch (const coatfft::InvalidArgument& e) {
      message = e.what();
    }
    CHECK(message.find(c.must_mention) != std::string::npos);
    CHECK(refused.stderr_text == "coatfft: error: " + message + "\n");
  }
  // A scene file that is not there, and a repeat count out of range.
  const fs::path missing = scratch("run_scene_missing.toml");
  fs::remove(missing);
  CHECK_THROWS_AS(coatfft::scene::run_scene(missing), coatfft::InvalidArgument);
  coatfft::scene::SceneRunOptions options;
  options.repeat = 0;
  CHECK_THROWS_WITH(coatfft::scene::run_scene(scratch("run_scene_bad_nx.toml"), options),
                    Catch::Contains("--repeat = 0"));
}
