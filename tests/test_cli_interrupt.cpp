// Ctrl-C during `coatfft run` (cli/signal_cleanup.hpp): a SIGINT in the middle of a long stress
// set-up stops the run within a second or two, the program says so, ends by SIGINT (status 130 in
// a shell) and leaves no output behind. The child is killed after a few seconds if it has not
// ended, so that an interrupt that does not work fails the test instead of hanging it.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli_process.hpp"

using namespace coatfft_test;
using namespace std::chrono_literals;

namespace {

// Stresses on 24 planes of a coated body at 192^2 cells: minutes of set-up on one core, against
// the second or so the test waits before its SIGINT.
const char* kLongStressScene = R"([grid]
nx = 192
ny = 192
lx = 4.0e-3
ly = 4.0e-3
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 1.0e-4
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
[method]
name = "frf-split"
threads = 1
[stress]
depths = [2e-5, 3e-5, 4e-5, 5e-5, 6e-5, 7e-5, 8e-5, 9e-5, 1e-4, 1.1e-4, 1.2e-4, 1.3e-4,
          1.4e-4, 1.5e-4, 1.6e-4, 1.7e-4, 1.8e-4, 1.9e-4, 2e-4, 2.5e-4, 3e-4, 4e-4, 5e-4, 6e-4]
alpha = 16
)";

struct InterruptedRun {
  bool ended = false;           ///< before the child's time limit
  bool by_sigint = false;       ///< ended by SIGINT, as a shell sees status 130
  double seconds_after = -1.0;  ///< from the SIGINT to the end [s]
  std::string stderr_text;
};

// Runs `coatfft ARGS...`, sends it SIGINT after `delay`, and waits at most `limit` for its end
// (then kills it).
InterruptedRun interrupt_run(std::vector<std::string> args, std::chrono::milliseconds delay,
                             std::chrono::seconds limit) {
  const fs::path err = scratch("interrupt_stderr.txt");
  const std::string err_path = err.string();
  args.insert(args.begin(), COATFFT_EXE);
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid == 0) {  // only async-signal-safe calls here: the child is a copy of the test runner
    // SIGINT as a terminal's program gets it, also where the tests were started with it ignored
    // (a background job of a shell), which exec would pass on.
    signal(SIGINT, SIG_DFL);
    const int fd = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_WRONLY);
    if (fd < 0 || null < 0 || dup2(fd, STDERR_FILENO) < 0 || dup2(null, STDOUT_FILENO) < 0)
      _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  REQUIRE(pid > 0);
  std::this_thread::sleep_for(delay);
  kill(pid, SIGINT);
  const auto sent = std::chrono::steady_clock::now();
  InterruptedRun run;
  int raw = 0;
  while (waitpid(pid, &raw, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - sent > limit) {
      kill(pid, SIGKILL);
      waitpid(pid, &raw, 0);
      break;
    }
    std::this_thread::sleep_for(10ms);
  }
  run.seconds_after =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  run.ended = !(WIFSIGNALED(raw) && WTERMSIG(raw) == SIGKILL);
  run.by_sigint = WIFSIGNALED(raw) && WTERMSIG(raw) == SIGINT;
  std::ifstream in(err);
  run.stderr_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return run;
}

}  // namespace

TEST_CASE("Ctrl-C stops coatfft run promptly, says so, and leaves no output", "[cli][interrupt]") {
  const fs::path scene = write_scene(kLongStressScene, "interrupt_stress", "", "");
  // A folder of its own: after the run it must be as empty as before (no OUTDIR, no staging).
  const fs::path folder = scratch("interrupt_run");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path out = folder / "out";
  const InterruptedRun run =
      interrupt_run({"run", scene.string(), "-o", out.string()}, 1500ms, 20s);
  INFO(run.stderr_text);
  INFO("ended " << run.seconds_after << " s after SIGINT");
  REQUIRE(run.ended);
  CHECK(run.by_sigint);
  // About a second on a loaded machine; 5 s leaves room without hiding a missing check.
  CHECK(run.seconds_after < 5.0);
  CHECK(run.stderr_text.find("coatfft: interrupted\n") != std::string::npos);
  CHECK(fs::is_empty(folder));
}
