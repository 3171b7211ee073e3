// One row of the speed-against-error sweep, run by bench_sweep as a child process so that the
// row's peak resident set is its own (wait4's rusage in the parent): builds the row's operator
// (timed as setup, by parts: bench/timed_setup.hpp), applies it once to warm up and then
// repeatedly for about --budget seconds (3 to 51 times; the median is reported), and writes the
// displacement and the timings for the parent (bench/sweep_row.hpp), which holds the reference.
#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <string>

#include "bench/command_line.hpp"
#include "bench/sweep_cases.hpp"
#include "bench/sweep_row.hpp"
#include "bench/timed_setup.hpp"
#include "core/detail/timing.hpp"
#include "loads/hertz_pressure.hpp"

int main(int argc, char** argv) {
  using namespace coatfft;
  coatfft::bench::CommandLine app{"One row of bench_sweep (run by bench_sweep, not by hand)"};
  sweep::RowSpec row;
  sweep::RowRun run;
  std::string method = "dcfft";
  std::string planning = "estimate";
  std::string g0;
  std::string output;
  app.add("--case", row.case_name, "Case name (bench/sweep_cases.hpp)").required();
  app.add("--method", method, "Method").required();
  app.add("--n", row.n, "Cells per side").required().range(1, 1 << 20);
  app.add("--alpha", row.alpha, "Extension ratio (frf-spectral, frf-dcfft)");
  app.add("--g0", g0, "g(0) method (frf-spectral, frf-dcfft)");
  app.add("--g0-tol", row.g0_tol, "g(0) tolerance");
  app.add("--planning", planning, "FFTW planner effort");
  app.add("--threads", run.threads, "Threads");
  app.add("--budget", run.budget_s, "Seconds of repeated applications");
  app.add("--output", output, "Displacement file (timings: the same name + .txt)").required();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    row.method = parse_method(method);
    run.planning = parse_planning(planning);
    if (!g0.empty()) row.g0 = parse_g0_method(g0);
    const sweep::SweepCase c = sweep::find_case(row.case_name);
    const Grid grid = sweep::case_grid(c, row.n);
    const Field p = hertz_pressure(grid, c.p0, c.a, c.sampling);
    const bench::TimedSetup setup =
        bench::timed_setup(grid, c.stack, sweep::operator_options(row, run));
    SurfaceOperator& op = *setup.built.op;
    Field u;
    const auto start = std::chrono::steady_clock::now();
    op.apply(p, u);  // warm-up; its result is the one written
    const double once = detail::seconds_since(start);
    sweep::RowTiming timing;
    timing.setup_s = setup.setup_s;
    timing.coeff_s = setup.kernel_s;
    timing.reps = std::clamp(static_cast<int>(run.budget_s / std::max(once, 1e-9)), 3, 51);
    Field scratch;
    timing.apply_s_median = detail::time_applications(op, p, scratch, timing.reps);
    sweep::write_row_result(output, u, timing);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_sweep_row: " << e.what() << "\n";
    return 1;
  }
}
