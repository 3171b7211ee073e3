#pragma once
// Runs a program as a child process and reports what the benchmarks need of it: its exit status,
// its own peak resident set size (wait4's rusage, not this process's high-water mark) and its
// wall time. Used where a benchmark row must be measured alone (bench_sweep, bench_dcfft) and by
// bench_peak_rss.
#include <string>
#include <vector>

namespace coatfft::bench {

struct ChildOutcome {
  int exit_code = -1;        ///< the child's exit status, or 128 + signal
  double peak_rss_mb = 0.0;  ///< the child's peak resident set [MiB] (ru_maxrss)
  double wall_s = 0.0;       ///< wall time from fork to wait [s]
};

/// Runs argv[0] (a path; a bare name is looked up in PATH as a shell would) with the arguments
/// argv[1...] (no shell) and waits for it. Throws coatfft::Error if it cannot be started.
ChildOutcome run_child(std::vector<std::string> argv);

/// The path of this process's executable (/proc/self/exe).
std::string self_executable();

}  // namespace coatfft::bench
