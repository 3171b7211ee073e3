// Nothing lost, nothing hung: the `coatfft` program never destroys a file that is not its own
// output, leaves OUTDIR byte-identical when it fails or is interrupted, refuses inputs that are
// not regular files and scenes that would exhaust memory, and names the key of every refusal.
// Each case reproduces a way the program once lost data, hung or said too little.
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/staged_output.hpp"
#include "core/error.hpp"
#include "tests/cli_process.hpp"
#include "tests/test_support.hpp"

using namespace coatfft_test;

namespace {

// A fresh, empty scratch folder.
fs::path fresh(const std::string& name) {
  const fs::path dir = scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

bool has_partial(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".partial") != std::string::npos) return true;
  return false;
}

// A refused command: exit 2, one line on stderr naming `must_mention`.
void check_refusal(const ProcessResult& result, const std::string& must_mention) {
  INFO(result.stderr_text);
  CHECK(result.status == 2);
  CHECK(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n') == 1);
  CHECK(result.stderr_text.find(must_mention) != std::string::npos);
  CHECK(result.stderr_text.find("internal error") == std::string::npos);
}

}  // namespace

TEST_CASE("frf -o refuses folders, FIFOs, links and the scene, and leaves nothing beside them",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_frf");
  const fs::path scene = write_scene(kGoodScene, "safety_frf/scene", "", "");
  fs::create_directory(dir / "folder");
  REQUIRE(mkfifo((dir / "fifo").c_str(), 0600) == 0);
  fs::create_symlink("/dev/null", dir / "link");
  const auto before = snapshot(dir);
  for (const char* target : {"folder", "fifo", "link", "scene.toml"}) {
    INFO(target);
    check_refusal(run_coatfft("frf " + scene.string() + " -o " + (dir / target).string()), target);
  }
  CHECK(snapshot(dir) == before);
  CHECK(fs::is_fifo(dir / "fifo"));
  CHECK(fs::is_symlink(dir / "link"));
  // A new name or a regular file is written.
  CHECK(run_coatfft("frf " + scene.string() + " -o " + (dir / "table.csv").string()).status == 0);
  CHECK(text_of(dir / "table.csv").rfind("k,kh_total,frf,frf_over_substrate\n", 0) == 0);
  CHECK_FALSE(has_partial(dir));
}

TEST_CASE("the wisdom file is never the scene, an output or a file of another kind",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_wisdom");
  std::ofstream(dir / "notes.txt") << "my notes\n";
  const std::string method = "[method]\nname = \"dcfft\"\nplanning = \"measure\"\nwisdom = ";
  const struct {
    const char* name;
    std::string wisdom;
    const char* must_mention;
  } cases[] = {{"self", "\"self.toml\"", "is an input"},
               {"notes", "\"notes.txt\"", "does not hold FFTW wisdom"},
               {"zero", "\"/dev/zero\"", "device"},
               {"output", "\"out/uz.npy\"", "is an output"}};
  for (const auto& c : cases) {
    INFO(c.name);
    const fs::path scene = write_scene(kGoodScene, std::string("safety_wisdom/") + c.name,
                                       "[method]\nname = \"dcfft\"", method + c.wisdom);
    const auto before = snapshot(dir);
    check_refusal(run_coatfft("run " + scene.string() + " -o " + (dir / "out").string()), "wisdom");
    CHECK(snapshot(dir) == before);
  }
}

TEST_CASE("a failed run leaves OUTDIR byte-identical", "[cli][safety]") {
  const fs::path dir = fresh("safety_half");
  const fs::path scene = write_scene(kGoodScene, "safety_half/scene", "", "");
  const fs::path out = dir / "out";
  REQUIRE(run_coatfft("run " + scene.string() + " -o " + out.string()).status == 0);
  // summary.json is now a folder: the run must stop before replacing uz.npy and the others.
  fs::remove(out / "summary.json");
  fs::create_directory(out / "summary.json");
  const auto before = snapshot(dir);
  check_refusal(run_coatfft("run " + scene.string() + " -o " + out.string()), "summary.json");
  CHECK(snapshot(dir) == before);
  // OUTDIR itself a regular file, or a device: refused, untouched.
  std::ofstream(dir / "file") << "x";
  const auto on_file = run_coatfft("run " + scene.string() + " -o " + (dir / "file").string());
  check_refusal(on_file, "file");
  CHECK_THAT(on_file.stderr_text, Catch::Contains("exists and is a regular file"));
  check_refusal(run_coatfft("run " + scene.string() + " -o /dev/null"), "/dev/null");
  CHECK(text_of(dir / "file") == "x");
  CHECK_FALSE(has_partial(dir));
}

TEST_CASE("outputs of an earlier run that the new run does not produce are removed, others kept",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_stale");
  const fs::path contact = write_scene(kSmallContactScene, "safety_stale/contact", "", "");
  const fs::path pressure = write_scene(kGoodScene, "safety_stale/pressure", "", "");
  const fs::path out = dir / "out";
  REQUIRE(run_coatfft("run " + contact.string() + " -o " + out.string()).status == 0);
  REQUIRE(fs::exists(out / "gap.npy"));
  std::ofstream(out / "mine.txt") << "user data";
  REQUIRE(run_coatfft("run " + pressure.string() + " -o " + out.string()).status == 0);
  CHECK_FALSE(fs::exists(out / "gap.npy"));  // written by coatfft, not produced now
  CHECK(text_of(out / "mine.txt") == "user data");
  CHECK(text_of(out / ".coatfft-outputs") ==
        "uz.npy\npressure.npy\ndisplacement.csv\nsummary.json\n");
  // A gap.npy that no coatfft run wrote is the user's: kept.
  std::ofstream(out / "gap.npy") << "user's own";
  REQUIRE(run_coatfft("run " + pressure.string() + " -o " + out.string()).status == 0);
  CHECK(text_of(out / "gap.npy") == "user's own");
}

// Runs `coatfft run SCENE -o OUT` in the background, sends SIGTERM as soon as a staging folder
// (a name with ".partial") appears in `watch` (the outputs are being written), and returns the
// program's exit status as the shell saw it.
int terminate_while_writing(const fs::path& scene, const fs::path& out, const fs::path& watch) {
  const fs::path status = scratch("safety_signal_status");
  const std::string run =
      std::string(COATFFT_EXE) + " run " + scene.string() + " -o " + out.string() + " 2>/dev/null";
  const std::string script =
      "cd " + watch.string() + " && { " + run + " & pid=$!; n=0; " +
      "while [ -z \"$(ls -A | grep partial)\" ] && [ $n -lt 6000 ]; do sleep 0.01; n=$((n+1)); "
      "done; kill -TERM $pid; wait $pid; echo $? > " +
      status.string() + "; }";
  REQUIRE(std::system(("sh -c '" + script + "'").c_str()) == 0);
  return std::stoi(text_of(status));
}

TEST_CASE("an interrupted run leaves no temporary files, and OUTDIR as it was", "[cli][safety]") {
  const fs::path dir = fresh("safety_signal");
  // 512^2 cells: about 30 MB of outputs, written in about 0.3 s, some twenty of the watch's polls.
  const fs::path scene =
      write_scene(kGoodScene, "safety_signal/scene", "nx = 33\nny = 33", "nx = 512\nny = 512");
  const fs::path out = dir / "out";
  // A new OUTDIR: staged beside it, nothing left.
  CHECK(terminate_while_writing(scene, out, dir) == 143);  // 128 + SIGTERM, re-raised
  CHECK_FALSE(has_partial(dir));
  CHECK_FALSE(fs::exists(out));
  // An existing OUTDIR with an earlier run's outputs: staged inside it, then byte-identical.
  const fs::path small = write_scene(kGoodScene, "safety_signal/small", "", "");
  REQUIRE(run_coatfft("run " + small.string() + " -o " + out.string()).status == 0);
  const auto before = snapshot(dir);
  CHECK(terminate_while_writing(scene, out, out) == 143);
  CHECK(snapshot(dir) == before);
}

// A disk that fills up, without privileges: a file-size limit (RLIMIT_FSIZE) on the run, its
// signal SIGXFSZ ignored so that writes past it fail with EFBIG as on a full disk. A file smaller
// than the stream's buffer fails only when it is closed.
TEST_CASE("a write that fails when its file is closed is an error, and OUTDIR stays as it was",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_full");
  const fs::path out = dir / "out";
  REQUIRE(run_coatfft("run " + write_scene(kGoodScene, "safety_full/scene", "", "").string() +
                      " -o " + out.string())
              .status == 0);
  // summary.json alone (979 bytes) under a limit of 512 bytes (sh's ulimit -f counts blocks).
  const fs::path summary_only =
      write_scene(std::string(kGoodScene) + "[output]\nfields = [\"summary\"]\n",
                  "safety_full/summary", "", "");
  const auto before = snapshot(dir);
  check_refusal(run_coatfft("run " + summary_only.string() + " -o " + out.string(),
                            "trap '' XFSZ; ulimit -f 1;"),
                "failed writing summary.json: File too large");
  CHECK(snapshot(dir) == before);
}

// The list of outputs written last, after the files (each of 4 bytes) it names (60 bytes), under
// a limit of 32 bytes: its failure stops the commit. In a child process, which takes the limit.
TEST_CASE("a list of outputs that cannot be written stops the commit", "[cli][safety]") {
  const fs::path out = fresh("safety_manifest");
  std::ofstream(out / "earlier.txt") << "the user's file";
  std::ofstream(out / coatfft::cli::StagedOutput::manifest_name) << "earlier.txt\n";
  const auto before = snapshot(out);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const rlimit limit{32, 32};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, SIG_IGN);
    int status = 1;
    try {
      const std::vector<std::string> names{"output_with_a_long_name_one.txt",
                                           "output_with_a_long_name_two.txt"};
      coatfft::cli::StagedOutput staged(out, names, {});
      for (const std::string& name : names) std::ofstream(staged.path(name)) << "data";
      staged.commit();
    } catch (const coatfft::InvalidArgument& e) {
      const std::string message = e.what();
      if (message.find("failed writing the list of outputs") != std::string::npos &&
          message.find("File too large") != std::string::npos)
        status = 0;
    }
    std::_Exit(status);
  }
  int status = -1;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(snapshot(out) == before);
}

// A run killed before it committed (SIGKILL, or an MPI job's rank 0 ended by its launcher) leaves
// its staging folder, named with its process number: the next run removes those of processes
// that no longer exist, and nothing else.
TEST_CASE("staging folders of killed runs are removed by the next run, others kept",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_dead");
  const fs::path out = dir / "out";
  const pid_t ended = ::fork();
  REQUIRE(ended >= 0);
  if (ended == 0) std::_Exit(0);
  REQUIRE(::waitpid(ended, nullptr, 0) == ended);  // a process number no process has now
  const std::string dead = std::to_string(ended);
  for (const fs::path& folder :
       {out / (".coatfft.partial-" + dead), dir / (".out.partial-" + dead),
        out / ".coatfft.partial-1", out / (".coatfft.partial-" + dead + "x"),
        out / (".other.partial-" + dead)})
    fs::create_directories(folder);
  std::ofstream(out / (".coatfft.partial-" + dead) / "uz.npy") << "half written";
  REQUIRE(run_coatfft("run " + write_scene(kGoodScene, "safety_dead/scene", "", "").string() +
                      " -o " + out.string())
              .status == 0);
  CHECK_FALSE(fs::exists(out / (".coatfft.partial-" + dead)));
  CHECK_FALSE(fs::exists(dir / (".out.partial-" + dead)));
  CHECK(fs::exists(out / ".coatfft.partial-1"));  // init's: alive
  CHECK(fs::exists(out / (".coatfft.partial-" + dead + "x")));
  CHECK(fs::exists(out / (".other.partial-" + dead)));
}

TEST_CASE("inputs that are not regular files are refused at once", "[cli][safety]") {
  const fs::path dir = fresh("safety_inputs");
  REQUIRE(mkfifo((dir / "fifo.csv").c_str(), 0600) == 0);
  fs::create_symlink("/dev/zero", dir / "zero.csv");
  for (const char* name : {"fifo.csv", "zero.csv"}) {
    INFO(name);
    const fs::path scene = write_scene(kGoodScene, std::string("safety_inputs/") + name,
                                       "kind = \"hertz\"\np0 = 1.0e9\na = 1.0e-3",
                                       std::string("kind = \"file\"\npath = \"") + name + "\"");
    check_refusal(run_coatfft("run " + scene.string() + " -o " + (dir / "out").string()),
                  "not a regular file");
  }
  check_refusal(run_coatfft("run " + dir.string() + " -o " + (dir / "out").string()),
                "not a regular file");
  check_refusal(
      run_coatfft("run " + (dir / "missing.toml").string() + " -o " + (dir / "out").string()),
      "cannot open");
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("counts and sizes have caps, refused before memory is spent", "[cli][safety]") {
  const fs::path out = scratch("safety_caps_out");
  fs::remove_all(out);
  const fs::path good = write_scene(kGoodScene, "safety_caps", "", "");
  check_refusal(
      run_coatfft("run " + good.string() + " -o " + out.string() + " --repeat 2147483647"),
      "--repeat");
  check_refusal(run_coatfft("run " + good.string() + " -o " + out.string() + " --repeat abc"),
                "--repeat");
  check_refusal(run_coatfft("frf " + good.string() + " --points 2000000000"), "--points");
  // 65536^2 cells: about 480 GB; refused with the keys, and the refusal itself stays small.
  const fs::path huge =
      write_scene(kGoodScene, "safety_caps_huge", "nx = 33\nny = 33", "nx = 65536\nny = 65536");
  check_refusal(run_coatfft("run " + huge.string() + " -o " + out.string()), "nx = 65536");
  const MeasuredRun measured = run_coatfft_measured("run " + huge.string() + " -o " + out.string());
  CHECK(measured.status == 2);
  CHECK(measured.peak_rss_mib < 100.0);
  const fs::path alpha = write_scene(kGoodScene, "safety_caps_alpha", "name = \"dcfft\"",
                                     "name = \"frf-spectral\"\nalpha = 1e6");
  check_refusal(run_coatfft("run " + alpha.string() + " -o " + out.string()), "alpha");
  check_refusal(run_coatfft("run " + good.string() + " -o " + out.string() + " --max-memory 10K"),
                "--max-memory");
  check_refusal(run_coatfft("run " + good.string() + " -o " + out.string() + " --max-memory 4Q"),
                "--max-memory");
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("an automatic choice too large for the memory is refused by the memory check",
          "[cli][safety]") {
  // A coated 16384^2 scene: the least any method needs (dcfft's padded lattice, about 30 GB) is
  // checked before the choice, whose lattice sizing would otherwise speak first, in its own terms.
  const std::string scene = R"([grid]
nx = 16384
ny = 16384
lx = 1e-3
ly = 1e-3
[substrate]
material = "steel"
[[coating]]
material = "alumina"
thickness = 1e-5
[pressure]
kind = "hertz"
p0 = 1e9
a = 1e-4
[method]
name = "auto"
)";
  const fs::path path = write_scene(scene, "safety_auto_memory", "", "");
  const fs::path out = scratch("safety_auto_memory_out");
  fs::remove_all(out);
  for (const std::string& command :
       {"run " + path.string() + " -o " + out.string(), "check " + path.string()}) {
    INFO(command);
    const ProcessResult r = run_coatfft(command + " --max-memory 4G");
    check_refusal(r, "the scene needs about");
    CHECK(r.stderr_text.find("nx = 16384, ny = 16384 (padded 32768 x 32768 transform)") !=
          std::string::npos);
  }
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("a max-memory beyond what 64 bits address is refused by name", "[cli][safety]") {
  const fs::path good = scene_with("safety_memory_good", "", "");
  // 1.1e32 bytes and, through the unit, an infinite double: both were accepted as limits.
  for (const char* size : {"99999999999999999999T", "1e300T", "17179869185G"}) {
    INFO(size);
    check_refusal(run_coatfft("check " + good.string() + " --max-memory " + size), "--max-memory");
  }
  CHECK(run_coatfft("check " + good.string() + " --max-memory 16777215T").status == 0);
}

TEST_CASE("extreme numbers are refused with the key, never as an internal error", "[cli][safety]") {
  const std::array cases{
      BadCase{"lx_2p53", "lx = 3.0e-3", "lx = 9007199254740993", "[pressure] a"},
      BadCase{"ly_int64", "ly = 3.0e-3", "ly = 9223372036854775807", "ly"},
      BadCase{"lx_tiny", "lx = 3.0e-3\nly = 3.0e-3", "lx = 1e-300\nly = 1e-300", "lx"},
      BadCase{"lx_huge", "lx = 3.0e-3", "lx = 1e308", "lx"},
      BadCase{"thickness_int64", "[pressure]",
              "[[coating]]\nmaterial = \"titanium_nitride\"\nthickness = 9223372036854775807\n"
              "[pressure]",
              "dcfft"},
      BadCase{"E_tiny", "material = \"steel\"", "E = 1e-308\nnu = 0.3", "[substrate] E"},
      BadCase{"p0_huge", "p0 = 1.0e9", "p0 = 1e308", "pressure"},
      BadCase{"a_below_cell", "a = 1.0e-3", "a = 1e-9", "[pressure] a"},
      BadCase{"alpha_dcfft", "name = \"dcfft\"", "name = \"dcfft\"\nalpha = 4.0", "alpha"},
      BadCase{"g0_direct", "name = \"dcfft\"", "name = \"direct\"\ng0 = \"quadrature\"", "g0"},
      BadCase{"nu_limit", "material = \"steel\"", "E = 2e11\nnu = 0.49999999", "0.4999"},
      BadCase{"long_name", "material = \"steel\"",
              "material = \"" + std::string(100000, 'x') + "\"", "unknown material"},
  };
  for (const auto& c : cases) check_refused(kGoodScene, c);
  // The documented limit of 64 coatings (docs/scene_format.md), named in the message.
  std::string coatings;
  for (int n = 0; n < 100; ++n) coatings += "[[coating]]\nmaterial = \"steel\"\nthickness = 1e-6\n";
  check_refused(kGoodScene, BadCase{"coatings_100", "[pressure]", coatings + "[pressure]", "64"});
  // The long name is shortened in the message.
  const fs::path scene = write_scene(kGoodScene, "long_name", "material = \"steel\"",
                                     "material = \"" + std::string(100000, 'x') + "\"");
  CHECK(run_coatfft("run " + scene.string() + " -o " + scratch("long_out").string())
            .stderr_text.size() < 400);
  const fs::path indenter = write_scene(kSmallContactScene, "indenter_int64", "load = 10.0",
                                        "load = 10.0\nindenter_E = -9223372036854775808\n"
                                        "indenter_nu = 0.3");
  check_refusal(run_coatfft("run " + indenter.string() + " -o " + scratch("ind_out").string()),
                "indenter_E");
}

TEST_CASE("messages: version, unknown command, one contact-edge line", "[cli][safety]") {
  const ProcessResult version = run_coatfft("--version");
  CHECK(version.status == 0);
  check_refusal(run_coatfft("frobnicate"), "unknown command \"frobnicate\"");
  const fs::path edge = write_scene(kSmallContactScene, "edge", "load = 10.0", "load = 1e6");
  const ProcessResult result =
      run_coatfft("run " + edge.string() + " -o " + scratch("edge_out").string());
  check_refusal(result, "enlarge [grid] lx and ly");
  // Said once.
  CHECK(result.stderr_text.find("domain edge") == result.stderr_text.rfind("domain edge"));
}

TEST_CASE("the FRF pipelines warn above 1e-2 predicted error and refuse above 1", "[cli][safety]") {
  // TiN 2 um on steel, 64 x 64 cells. Square cells: Spinu's (2021) pipelines at alpha = 2 are
  // about 2.5 % off (docs/validation/frf_pipelines.md), so a warning with the prediction. Cells
  // with dx/dy = 100: the pipelines' result is off by more than max |u| itself; refused, with
  // the exact method named.
  const std::string base = kPipelineWarningScene;
  const fs::path out = scratch("pipeline_warning_out");
  fs::remove_all(out);
  const fs::path square = write_scene(base, "pipeline_square", "", "");
  const ProcessResult warned = run_coatfft("run " + square.string() + " -o " + out.string());
  INFO(warned.stderr_text);
  CHECK(warned.status == 0);
  CHECK(warned.stderr_text.find("coatfft: warning: method frf-spectral: predicted error") == 0);
  nlohmann::json summary;
  std::ifstream(out / "summary.json") >> summary;
  CHECK(summary["predicted_error"].get<double>() > 1e-2);
  CHECK(summary["predicted_error"].get<double>() < 4e-2);
  REQUIRE(summary["warnings"].size() == 1);
  CHECK(summary["warnings"][0].get<std::string>().find("frf-split") != std::string::npos);
  // frf-split is exact: no warning, an empty list.
  const fs::path split = write_scene(base, "pipeline_split", "frf-spectral", "frf-split");
  const fs::path split_out = scratch("pipeline_split_out");
  fs::remove_all(split_out);
  REQUIRE(run_coatfft("run " + split.string() + " -o " + split_out.string()).status == 0);
  std::ifstream(split_out / "summary.json") >> summary;
  CHECK(summary["warnings"].empty());
  CHECK_FALSE(summary.contains("predicted_error"));

  const fs::path anisotropic = write_scene(base, "pipeline_anisotropic", "ly = 4e-3\n[substrate]",
                                           "ly = 40e-6\n[substrate]");
  const std::string thin_load = "a = 13e-6\nsampling = \"cell_average\"";
  const fs::path refused =
      write_scene(text_of(anisotropic), "pipeline_anisotropic", "a = 1e-3", thin_load);
  for (const char* method : {"frf-spectral", "frf-dcfft"}) {
    INFO(method);
    const fs::path scene =
        write_scene(text_of(refused), std::string("pipeline_") + method, "frf-spectral", method);
    fs::remove_all(out);
    check_refusal(run_coatfft("run " + scene.string() + " -o " + out.string()), "frf-split");
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("coatfft check validates as run does, prints the plan and writes nothing",
          "[cli][safety]") {
  const fs::path dir = fresh("safety_check");
  const fs::path scene = write_scene(kGoodScene, "safety_check/scene", "", "");
  const auto before = snapshot(dir);
  std::string text;
  {
    FILE* pipe = popen((std::string(COATFFT_EXE) + " check " + scene.string()).c_str(), "r");
    REQUIRE(pipe != nullptr);
    char buffer[4096];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    CHECK(pclose(pipe) == 0);
  }
  const nlohmann::json plan = nlohmann::json::parse(text);
  CHECK(plan["method"] == "dcfft");
  CHECK(plan["problem"] == "pressure");
  CHECK(plan["nx"] == 33);
  // The estimate of docs/scene_format.md: the program's 10 MiB, 4 fields + 20 bytes per cell of
  // the padded lattice,
  // 70 x 70 (the smallest even 7-smooth length >= 2 n - 1 = 65).
  CHECK(plan["estimated_memory_bytes"].get<double>() ==
        10.0 * 1024 * 1024 + 8.0 * 4 * 33 * 33 + 20.0 * 70 * 70);
  CHECK(plan["warnings"].empty());
  CHECK(snapshot(dir) == before);
  // What run refuses before computing, check refuses too.
  const fs::path narrow = write_scene(kGoodScene, "safety_check/narrow", "a = 1.0e-3", "a = 1e-9");
  check_refusal(run_coatfft("check " + narrow.string()), "[pressure] a");
  check_refusal(run_coatfft("check " + scene.string() + " --max-memory 10K"), "--max-memory");
  CHECK(snapshot(dir).size() == before.size() + 1);  // narrow.toml, nothing else
}

TEST_CASE(
    "started by an MPI launcher with several ranks, the program refuses once and writes nothing",
    "[cli][safety]") {
  // The launcher's variables as Open MPI's mpirun sets them for each rank (no MPI is started:
  // `check` does not run distributed; `run` and `surface` do, tests/mpi_cli_*).
  const fs::path dir = fresh("safety_mpi");
  const fs::path scene = write_scene(kGoodScene, "safety_mpi/scene", "", "");
  const std::string check = "check " + scene.string();
  check_refusal(run_coatfft(check, "OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=0"),
                "MPI launcher with 3 ranks, but `check`");
  const ProcessResult other = run_coatfft(check, "OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=2");
  CHECK(other.status == 2);
  CHECK(other.stderr_text.empty());
  // One rank is a serial run.
  const std::string args = "run " + scene.string() + " -o " + (dir / "out").string();
  CHECK(run_coatfft(args, "OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0").status == 0);
  CHECK(fs::exists(dir / "out" / "summary.json"));
}

TEST_CASE("a topography's pad is checked against the memory before its gap is allocated",
          "[cli][safety]") {
  // pad = 30000 made a 60008^2 gap while the scene was read, before any memory check: "out of
  // memory" under --max-memory 2G, in check as in run. Now refused by the pad, at once.
  const fs::path dir = fresh("safety_pad");
  {
    std::ofstream z(dir / "z.csv");
    for (int j = 0; j < 4; ++j) z << "0,1e-7,2e-7,1e-7\n";
  }
  std::ofstream(dir / "scene.toml") << "[grid]\nlx = 1e-3\nly = 1e-3\npad = 30000\n"
                                       "[substrate]\nmaterial = \"steel\"\n"
                                       "[contact]\ntopography = \"z.csv\"\nload = 1.0\n";
  const fs::path out = dir / "out";
  for (const std::string& command :
       {"run " + (dir / "scene.toml").string() + " -o " + out.string() + " --max-memory 2G",
        "check " + (dir / "scene.toml").string() + " --max-memory 2G",
        "check " + (dir / "scene.toml").string()}) {
    INFO(command);
    const ProcessResult r = run_coatfft(command);
    check_refusal(r,
                  "[grid] pad = 30000 (the map's 4 x 4 points and 30000 cells on each side): "
                  "[grid] nx = 60004, ny = 60004");
  }
  CHECK_FALSE(fs::exists(out));
  // The same map with a pad the machine holds runs.
  std::ofstream(dir / "small.toml") << "[grid]\nlx = 1e-3\nly = 1e-3\npad = 2\n"
                                       "[substrate]\nmaterial = \"steel\"\n"
                                       "[contact]\ntopography = \"z.csv\"\nload = 1.0\n";
  CHECK(run_coatfft("check " + (dir / "small.toml").string() + " --max-memory 2G").status == 0);
}

TEST_CASE("a file of the user's with an output's name is never replaced", "[cli][safety]") {
  // A folder holding the user's own fields.nc (or uz.npy) that no coatfft run wrote: the run was
  // refused nowhere and replaced it. Now refused before any work, OUTDIR byte for byte as it was;
  // the same outputs written by an earlier run (listed in .coatfft-outputs) are replaced.
  const fs::path dir = fresh("safety_users_file");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::ofstream(out / "fields.nc") << "my own NetCDF file";
  std::ofstream(out / "notes.txt") << "notes";
  const fs::path netcdf = write_scene(std::string(kGoodScene) + "[output]\nformat = \"netcdf\"\n",
                                      "safety_users_file/netcdf", "", "");
  const auto before = snapshot(dir);
  check_refusal(run_coatfft("run " + netcdf.string() + " -o " + out.string()),
                "fields.nc\" exists and no coatfft run wrote it");
  CHECK(snapshot(dir) == before);
  // The user moves the file away; the run writes fields.nc, and a second run replaces its own.
  fs::rename(out / "fields.nc", dir / "mine.nc");
  REQUIRE(run_coatfft("run " + netcdf.string() + " -o " + out.string()).status == 0);
  REQUIRE(run_coatfft("run " + netcdf.string() + " -o " + out.string()).status == 0);
  CHECK(text_of(out / ".coatfft-outputs") == "fields.nc\ndisplacement.csv\nsummary.json\n");
  // A .npy run into the same folder: fields.nc is stale (coatfft's) and removed; a uz.npy of the
  // user's would stop it.
  std::ofstream(out / "uz.npy") << "mine";
  const fs::path npy = write_scene(kGoodScene, "safety_users_file/npy", "", "");
  check_refusal(run_coatfft("run " + npy.string() + " -o " + out.string()), "uz.npy");
  CHECK(text_of(out / "uz.npy") == "mine");
  fs::remove(out / "uz.npy");
  REQUIRE(run_coatfft("run " + npy.string() + " -o " + out.string()).status == 0);
  CHECK_FALSE(fs::exists(out / "fields.nc"));
  CHECK(text_of(out / "notes.txt") == "notes");
}
