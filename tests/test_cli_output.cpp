// The [output] section of a scene: `coatfft run` writes the files it names (and summary.json,
// always), byte for byte as a full run writes them, checks and replaces no others, and refuses
// lists it cannot honour with one line and no output.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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
  };
  for (const auto& c : cases) check_refused(kGoodScene, c);
  // coatfft check reads the scene as run does.
  const fs::path scene = write_scene(kGoodScene, "output_check", method, with("fields = []\n"));
  const ProcessResult checked = run_coatfft("check " + scene.string());
  CHECK(checked.status == 2);
  CHECK(checked.stderr_text.find("[output] fields") != std::string::npos);
}
