// Progress of `coatfft run` (cli/progress.hpp): when it is printed (after the first second, on a
// terminal, without --quiet) and what it looks like, with the clock given to Progress by the test;
// then the program itself on a pseudo-terminal and with stderr redirected to a file.
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/progress.hpp"
#include "tests/cli_process.hpp"

using namespace coatfft_test;
using coatfft::cli::Progress;
using coatfft::cli::progress_wanted;
using namespace std::chrono_literals;

namespace {

const Progress::Clock::time_point t0{};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A contact whose setup and solve take 1.5 to 3 s in a Release build on one core of 2024 (84
// iterations on 512^2 cells): long enough to show iterations after the first second.
const char* kSlowContact = R"([grid]
nx = 512
ny = 512
lx = 3.0e-3
ly = 3.0e-3
[substrate]
material = "steel"
[contact]
indenter = "sphere"
radius = 0.01
load = 10.0
[output]
fields = ["summary"]
)";

struct TerminalRun {
  int status = -1;
  std::string text;  ///< all the program wrote, stdout and stderr (one terminal)
};

// Runs `coatfft ARGS` with a pseudo-terminal as its stdin, stdout and stderr, reading all it
// writes until it closes the terminal.
TerminalRun run_on_terminal(std::vector<std::string> args) {
  args.insert(args.begin(), COATFFT_EXE);
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  // The child must not inherit output that the test runner has not written yet.
  std::cout.flush();
  std::cerr.flush();
  int terminal = -1;
  const pid_t pid = forkpty(&terminal, nullptr, nullptr, nullptr);
  if (pid == 0) {  // nothing but exec here: the child is a copy of the test runner
    execv(argv[0], argv.data());
    _exit(127);
  }
  REQUIRE(pid > 0);
  TerminalRun run;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(terminal, buffer, sizeof buffer);
    if (n > 0) {
      run.text.append(buffer, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // end of file, or EIO on Linux once the program's side is closed
    }
  }
  int raw = 0;
  waitpid(pid, &raw, 0);
  close(terminal);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return run;
}

}  // namespace

TEST_CASE("progress is wanted on a terminal without --quiet only", "[cli][progress]") {
  CHECK(progress_wanted(false, true));
  CHECK_FALSE(progress_wanted(true, true));
  CHECK_FALSE(progress_wanted(false, false));
  CHECK_FALSE(progress_wanted(true, false));
}

TEST_CASE("Progress is silent in the first second, then prints stages and iterations",
          "[cli][progress]") {
  std::ostringstream out;
  {
    Progress progress(true, out, t0);
    progress.stage("setting up the operator (dcfft)", t0 + 500ms);
    progress.iteration(1, 0.5, t0 + 900ms);
    CHECK(out.str().empty());
    progress.stage("solving the contact", t0 + 1200ms);
    std::string expected = "coatfft [1.2 s] solving the contact\n";
    CHECK(out.str() == expected);
    // Iterations: one line updated in place, at most once per 0.25 s.
    progress.iteration(5, 0.25, t0 + 1300ms);
    CHECK(out.str() == expected);
    progress.iteration(9, 0.25, t0 + 1500ms);
    expected += "\rcoatfft [1.5 s] contact solve: iteration 9, residual 0.25";
    CHECK(out.str() == expected);
    progress.iteration(10, 0.003, t0 + 1800ms);
    expected += "\rcoatfft [1.8 s] contact solve: iteration 10, residual 0.003";
    CHECK(out.str() == expected);
    // A shorter line covers the rest of the longer one with blanks.
    progress.iteration(11, 1e-3, t0 + 2100ms);
    expected += "\rcoatfft [2.1 s] contact solve: iteration 11, residual 0.001";
    CHECK(out.str() == expected);
    progress.iteration(12, 1, t0 + 2400ms);
    expected += "\rcoatfft [2.4 s] contact solve: iteration 12, residual 1" + std::string(4, ' ');
    CHECK(out.str() == expected);
    // A stage ends the open line first; stages are not throttled.
    progress.stage("writing summary.json", t0 + 2450ms);
    progress.finish(t0 + 2500ms);
    expected += "\ncoatfft [2.5 s] writing summary.json\ncoatfft [2.5 s] done\n";
    CHECK(out.str() == expected);
    progress.iteration(13, 0.5, t0 + 3000ms);  // left open ...
  }
  // ... and ended by the destructor, so that an error message after it starts a line.
  CHECK(out.str().back() == '\n');
  CHECK(contains(out.str(), "iteration 13, residual 0.5\n"));
}

TEST_CASE("Progress::tick keeps a long stage's lines going, within a second", "[cli][progress]") {
  std::ostringstream out;
  {
    Progress progress(true, out, t0);
    progress.tick(t0 + 1500ms);  // no stage yet: nothing to say
    progress.stage("stresses on 3 planes", t0 + 100ms);
    progress.tick(t0 + 900ms);  // within the first second: silent
    CHECK(out.str().empty());
    progress.tick(t0 + 1100ms);  // a line of its own, which a reader of lines sees at once
    std::string expected = "coatfft [1.1 s] stresses on 3 planes ...\n";
    CHECK(out.str() == expected);
    progress.tick(t0 + 1600ms);  // not 0.9 s since the last line
    CHECK(out.str() == expected);
    progress.tick(t0 + 2000ms);
    expected += "coatfft [2.0 s] stresses on 3 planes ...\n";
    CHECK(out.str() == expected);
  }
}

TEST_CASE("Progress names the step a stage is on: a sweep's value, a plane", "[cli][progress]") {
  std::ostringstream out;
  {
    Progress progress(true, out, t0);
    progress.stage("solving the contact (load control, a sweep)", t0 + 100ms);
    progress.step("load 1 of 3: 10 N", t0 + 200ms);  // within the first second: silent
    CHECK(out.str().empty());
    progress.iteration(7, 0.5, t0 + 1100ms);  // the iterations are the step's
    std::string expected =
        "\rcoatfft [1.1 s] load 1 of 3: 10 N, contact solve: iteration 7, residual 0.5";
    CHECK(out.str() == expected);
    progress.step("load 2 of 3: 20 N", t0 + 1200ms);  // within 0.25 s of the last line: kept ...
    CHECK(out.str() == expected);
    progress.tick(t0 + 2050ms);  // ... and shown by the next line, with the stage
    expected +=
        "\ncoatfft [2.0 s] solving the contact (load control, a sweep): load 2 of 3: 20 N ...\n";
    CHECK(out.str() == expected);
    progress.step("load 3 of 3: 40 N", t0 + 2300ms);
    expected += "coatfft [2.3 s] solving the contact (load control, a sweep): load 3 of 3: 40 N\n";
    CHECK(out.str() == expected);
    // A new stage has no step until it reports one.
    progress.stage("stresses on 21 planes", t0 + 2400ms);
    progress.tick(t0 + 3400ms);
    expected +=
        "coatfft [2.4 s] stresses on 21 planes\ncoatfft [3.4 s] stresses on 21 planes ...\n";
    CHECK(out.str() == expected);
  }
}

TEST_CASE("Progress prints nothing for a short run or when it is disabled", "[cli][progress]") {
  std::ostringstream out;
  {
    Progress progress(true, out, t0);
    progress.stage("setting up the operator (dcfft)", t0 + 100ms);
    progress.iteration(3, 0.1, t0 + 900ms);
    progress.finish(t0 + 950ms);
  }
  {
    Progress progress(false, out, t0);
    progress.stage("setting up the operator (dcfft)", t0 + 5s);
    progress.tick(t0 + 7s);
    progress.iteration(3, 0.1, t0 + 10s);
    progress.finish(t0 + 20s);
  }
  CHECK(out.str().empty());
}

TEST_CASE("coatfft run shows progress on a terminal, and --quiet silences it", "[cli][progress]") {
  const std::string scene = write_scene(kSlowContact, "progress_terminal", "", "").string();
  const std::string out = scratch("progress_terminal_out").string();
  const TerminalRun shown = run_on_terminal({"run", scene, "-o", out});
  INFO(shown.text);
  REQUIRE(shown.status == 0);
  // Progress starts one second after the run; the run's own clock says whether its solve went on
  // long enough (0.25 s more) to have an iteration shown. A machine so fast that it did not is
  // told so rather than failing.
  nlohmann::json summary;
  std::ifstream(fs::path(out) / "summary.json") >> summary;
  const double seconds =
      summary["setup_seconds"].get<double>() + summary["solve_seconds"].get<double>();
  if (seconds < 1.25) {
    WARN("setup and solve took only " << seconds << " s: too short to show progress");
  } else {
    CHECK(contains(shown.text, "contact solve: iteration "));
    CHECK(contains(shown.text, "] writing summary.json"));
    CHECK(contains(shown.text, "] done"));
  }
  const TerminalRun quiet = run_on_terminal({"run", scene, "-o", out, "--quiet"});
  CHECK(quiet.status == 0);
  CHECK(quiet.text.empty());
}

TEST_CASE("coatfft run prints no progress when stderr is not a terminal", "[cli][progress]") {
  const fs::path scene = write_scene(kSlowContact, "progress_redirected", "", "");
  const ProcessResult result =
      run_coatfft("run " + scene.string() + " -o " + scratch("progress_redirected_out").string());
  CHECK(result.status == 0);
  CHECK(result.stderr_text.empty());
}

TEST_CASE("warnings are printed under --quiet too", "[cli][progress]") {
  // An FRF pipeline with a predicted error above 1e-2 (TiN 2 um on steel, 64^2, frf-spectral):
  // its warning is about the result, not progress, and is printed under --quiet too.
  const std::string base = kPipelineWarningScene;
  const fs::path scene = write_scene(base, "progress_quiet_warning", "", "");
  const ProcessResult result = run_coatfft("run " + scene.string() + " -o " +
                                           scratch("progress_quiet_out").string() + " --quiet");
  INFO(result.stderr_text);
  CHECK(result.status == 0);
  CHECK(result.stderr_text.rfind("coatfft: warning: method frf-spectral: predicted error", 0) == 0);
}
