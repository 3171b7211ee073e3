// Runs a command as a child process and prints its peak resident set size [MiB] (wait4's rusage,
// the child's own), its wall time and its exit status, which becomes this program's. Used by
// scripts/run_benchmarks.sh for the memory of a whole coatfft run.
//   bench_peak_rss CMD [ARGS...]
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "bench/child_process.hpp"
#include "bench/command_line.hpp"

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{
      "Peak resident set size of a command: bench_peak_rss CMD [ARGS...]"};
  app.leave_the_rest();  // CMD and everything after it are the command's, not ours
  if (const auto status = app.parse(argc, argv)) return *status;
  const std::vector<std::string> command = app.rest();
  if (command.empty()) {
    std::cerr << "bench_peak_rss: no command given\n" << app.help();
    return 2;
  }
  try {
    const coatfft::bench::ChildOutcome out = coatfft::bench::run_child(command);
    std::cout << "peak_rss_mb = " << out.peak_rss_mb << "\nwall_s = " << out.wall_s
              << "\nexit_code = " << out.exit_code << "\n";
    return out.exit_code;
  } catch (const std::exception& e) {
    std::cerr << "bench_peak_rss: " << e.what() << "\n";
    return 1;
  }
}
