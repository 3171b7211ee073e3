// Speed against error: sweeps method x grid x alpha x g(0) choice on Hertz loads over homogeneous
// and coated half-spaces (bench/sweep_cases.hpp) and writes one CSV row per setting, with
// "# key = value" headers (machine, compiler, flags, FFTW version, threads, date). Errors are in
// the measure of Spinu (2021, Fig. 2): (u - u_ref) / u_ref(0), max and RMS over the grid's cells.
//
// Every row runs in a child process (bench_sweep_row, found next to this program), so that the
// peak resident set size of the row is the child's own (wait4's rusage), not the high-water mark
// of the sweep; the child writes its displacement to a temporary file and this program, which
// holds the reference field, computes the errors.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/child_process.hpp"
#include "bench/command_line.hpp"
#include "bench/sweep_cases.hpp"
#include "bench/sweep_row.hpp"
#include "convolution/fft/planning.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/method.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

namespace {

namespace sweep = coatfft::sweep;
using coatfft::Field;
using coatfft::Method;
using coatfft::detail::seconds_since;
using sweep::fmt;

struct SweepConfig {
  std::string mode = "full";
  std::string output;
  std::string row_program;
  sweep::RowRun run;
  std::vector<std::string> cases;  // empty: all of the mode
  std::vector<Method> methods;     // empty: all
  std::vector<std::ptrdiff_t> grids;
  std::vector<double> alphas;
  std::vector<std::pair<coatfft::G0Method, double>> g0s;
  std::ptrdiff_t direct_max_n = 64;
  std::ptrdiff_t max_extended = 4096;   // cap on M = alpha N per axis (memory and time)
  std::ptrdiff_t quadrature_max_n = 0;  // g(0) by quadrature only up to this N (0: all)
};

SweepConfig mode_config(const std::string& mode) {
  using coatfft::G0Method;
  SweepConfig cfg;
  cfg.mode = mode;
  const double regularized_tol = coatfft::default_g0_tolerance;
  cfg.g0s = {{G0Method::regularized, regularized_tol},
             {G0Method::quadrature, 1e-4},
             {G0Method::quadrature, 1e-8}};
  cfg.alphas = {2.0, 4.0, 8.0};
  if (mode == "tiny") {
    cfg.grids = {32, 64};
    cfg.alphas = {2.0, 4.0};
    cfg.g0s = {{G0Method::regularized, regularized_tol}, {G0Method::quadrature, 1e-4}};
    cfg.run.budget_s = 0.02;
    cfg.cases = {"hertz_homogeneous"};
  } else if (mode == "quick") {
    cfg.grids = {32, 64, 128, 256, 512};
    cfg.run.budget_s = 0.1;
  } else {
    cfg.grids = {32, 64, 128, 256, 512, 1024, 2048};
    cfg.run.budget_s = 0.3;
    cfg.direct_max_n = 128;
    // g(0) depends on alpha L only, not on N, so the quadrature variants shift u by the same
    // constant at every N: running them up to 256^2 shows their effect and saves minutes.
    cfg.quadrature_max_n = 256;
  }
  return cfg;
}

template <class T>
bool selected(const std::vector<T>& list, const T& item) {
  return list.empty() || std::find(list.begin(), list.end(), item) != list.end();
}

// The rows of case `c` at N = n: direct (small N), dcfft (both homogeneous only) and frf-split,
// then frf-spectral and frf-dcfft at every alpha and g(0) choice within the caps.
std::vector<sweep::RowSpec> plan_rows(const SweepConfig& cfg, const sweep::SweepCase& c,
                                      std::ptrdiff_t n) {
  std::vector<sweep::RowSpec> rows;
  for (const Method method : coatfft::all_methods) {
    if (coatfft::samples_frf_lattice(method) || !selected(cfg.methods, method)) continue;
    if (coatfft::uses_love_coefficients(method) && !c.stack.is_homogeneous()) continue;
    if (method == Method::direct && n > cfg.direct_max_n) continue;
    rows.push_back({c.name, method, n, 0.0, std::nullopt, 0.0});
  }
  for (const Method method : coatfft::all_methods) {
    if (!coatfft::samples_frf_lattice(method) || !selected(cfg.methods, method)) continue;
    for (const double alpha : cfg.alphas) {
      if (alpha * static_cast<double>(n) > static_cast<double>(cfg.max_extended)) continue;
      for (const auto& [g0, tol] : cfg.g0s) {
        if (g0 == coatfft::G0Method::quadrature && cfg.quadrature_max_n > 0 &&
            n > cfg.quadrature_max_n)
          continue;
        rows.push_back({c.name, method, n, alpha, g0, tol});
      }
    }
  }
  return rows;
}

// The "# key = value" header and the CSV column line of sweep.csv.
std::string sweep_header(const SweepConfig& cfg) {
  std::ostringstream header;
  header << "# bench = bench_sweep (speed against error)\n"
         << "# mode = " << cfg.mode << "\n";
  coatfft::bench::write_machine_header(header);
  header << "# threads = " << cfg.run.threads << "\n"
         << "# planning = " << to_string(cfg.run.planning) << "\n"
         << "# load = Hertz p0 = 1 GPa, a = 1 mm on [-1.5a, 1.5a]^2 (N x N cells)\n"
         << "# error = (u - u_ref) / u_ref(0): max_err = max |.|, rms_err = RMS over all cells\n"
         << "# setup_s = wall time of building the operator (coefficients or FRF samples, g(0), "
            "kernel transform, FFTW plans)\n"
         << "# coeff_s = the part of setup_s spent on the influence coefficients (Love, FRF "
            "samples or their inverse transform, split); 0 for frf-spectral\n"
         << "# apply_s_median = median of repeated applications after one warm-up\n"
         << "# peak_rss_mb = peak resident set of a child process doing only this row "
            "(pressure, operator, output; wait4 rusage)\n"
         << "# caps = alpha N <= " << cfg.max_extended << "; direct for N <= " << cfg.direct_max_n
         << "; g0 quadrature for N <= "
         << (cfg.quadrature_max_n > 0 ? std::to_string(cfg.quadrature_max_n) : "all") << "\n";
  for (const sweep::SweepCase& c : sweep::all_cases())
    if (selected(cfg.cases, c.name))
      header << "# case " << c.name << " = " << c.description << "; reference: " << c.reference
             << "\n";
  header << "case,method,N,alpha,g0,g0_tol,sampling,setup_s,apply_s_median,peak_rss_mb,max_err,"
            "rms_err,coeff_s\n";
  return header.str();
}

// One row in a child process (its own peak RSS), measured against `ref`: the CSV line, or a
// "# failed: ..." line when the child failed (counted in `failures`).
std::string run_row(const SweepConfig& cfg, const sweep::SweepCase& c, const sweep::RowSpec& row,
                    std::ptrdiff_t n, const sweep::Reference& ref, const std::string& tmp,
                    int& failures) {
  std::vector<std::string> argv = sweep::row_arguments(row, cfg.run, tmp);
  argv.insert(argv.begin(), cfg.row_program);
  const coatfft::bench::ChildOutcome child = coatfft::bench::run_child(argv);
  const std::string method(to_string(row.method));
  if (child.exit_code != 0) {
    ++failures;
    return "# failed: " + row.case_name + "," + method + "," + std::to_string(n) + "," +
           fmt(row.alpha) + "," + sweep::g0_label(row) + " (exit code " +
           std::to_string(child.exit_code) + ")\n";
  }
  sweep::RowTiming timing;
  const Field u = sweep::read_row_result(tmp, n, timing);
  const Field diff = (u - ref.u) / ref.u_centre;
  const double max_err = diff.abs().maxCoeff();
  const double rms_err = std::sqrt(diff.square().mean());
  COATFFT_REQUIRE(std::isfinite(max_err) && std::isfinite(rms_err), "non-finite error for ", method,
                  " N = ", n);
  std::ostringstream line;
  line << row.case_name << ',' << method << ',' << n << ',' << fmt(row.alpha) << ','
       << sweep::g0_label(row) << ',' << fmt(row.g0_tol) << ',' << sweep::to_string(c.sampling)
       << ',' << fmt(timing.setup_s) << ',' << fmt(timing.apply_s_median) << ','
       << fmt(child.peak_rss_mb) << ',' << fmt(max_err) << ',' << fmt(rms_err) << ','
       << fmt(timing.coeff_s) << '\n';
  return line.str();
}

int sweep_main(const SweepConfig& cfg) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::string header = sweep_header(cfg);
  std::cout << header << std::flush;

  const std::filesystem::path out_path(cfg.output);
  if (out_path.has_parent_path()) std::filesystem::create_directories(out_path.parent_path());
  std::ofstream out(cfg.output);
  COATFFT_REQUIRE(out.good(), "cannot write ", cfg.output);
  out << header << std::flush;

  const std::string tmp =
      (std::filesystem::temp_directory_path() / ("bench_sweep_" + std::to_string(getpid())))
          .string();
  int failures = 0;
  for (const sweep::SweepCase& c : sweep::all_cases()) {
    if (!selected(cfg.cases, c.name)) continue;
    const auto t_table = std::chrono::steady_clock::now();
    const sweep::RadialReference u_ref(c, sweep::max_radius(c));
    std::cerr << "[" << fmt(seconds_since(t_start)) << " s] " << c.name << ": radial reference ("
              << u_ref.nb_nodes() << " nodes) in " << fmt(seconds_since(t_table)) << " s\n";
    for (const std::ptrdiff_t n : cfg.grids) {
      const std::vector<sweep::RowSpec> rows = plan_rows(cfg, c, n);
      if (rows.empty()) continue;
      const auto t_ref = std::chrono::steady_clock::now();
      const sweep::Reference ref = sweep::reference(u_ref, sweep::case_grid(c, n));
      std::cerr << "[" << fmt(seconds_since(t_start)) << " s] " << c.name << " N = " << n
                << ": reference in " << fmt(seconds_since(t_ref)) << " s\n";
      for (const sweep::RowSpec& row : rows) {
        const std::string line = run_row(cfg, c, row, n, ref, tmp, failures);
        std::cout << line << std::flush;
        out << line << std::flush;
      }
    }
  }
  std::filesystem::remove(tmp);
  std::filesystem::remove(tmp + ".txt");
  const std::string footer = "# total_wall_s = " + fmt(seconds_since(t_start)) + "\n";
  std::cout << footer;
  out << footer;
  std::cerr << "written " << cfg.output << (failures ? " (with failed rows)" : "") << "\n";
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{
      "Speed against error: method x grid x alpha x g(0) on Hertz loads"};
  bool tiny = false, quick = false, full = false;
  auto& tiny_flag = app.flag("--tiny", tiny, "N = 32, 64; the homogeneous case only");
  auto& quick_flag = app.flag("--quick", quick, "N = 32 ... 512");
  app.flag("--full", full, "N = 32 ... 2048 (the default)")
      .excludes(tiny_flag)
      .excludes(quick_flag);
  tiny_flag.excludes(quick_flag);
  std::string output = std::string(COATFFT_SOURCE_DIR) + "/bench/results/sweep.csv";
  app.add("--output", output, "CSV file").show_default();
  int threads = 1;
  app.add("--threads", threads, "Threads of each operator").positive();
  std::string planning = "estimate";
  app.add("--planning", planning, "FFTW planner effort: estimate or measure");
  std::vector<std::string> cases, methods;
  app.add("--cases", cases, "Cases to run (default: all of the mode)").comma_separated();
  app.add("--methods", methods, "Methods to run (default: all)").comma_separated();
  std::vector<std::ptrdiff_t> grids;
  app.add("--grids", grids, "Grid sizes N (default: those of the mode)")
      .comma_separated()
      .range(std::ptrdiff_t{2}, std::ptrdiff_t{1} << 20);
  std::string row_program =
      (std::filesystem::path(coatfft::bench::self_executable()).parent_path() / "bench_sweep_row")
          .string();
  app.add("--row-program", row_program, "The bench_sweep_row program").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    SweepConfig cfg = mode_config(tiny ? "tiny" : quick ? "quick" : "full");
    cfg.output = output;
    cfg.row_program = row_program;
    cfg.run.threads = threads;
    cfg.run.planning = coatfft::parse_planning(planning);
    for (const std::string& name : cases) sweep::find_case(name);  // refuse unknown names now
    if (!cases.empty()) cfg.cases = cases;
    for (const std::string& name : methods) cfg.methods.push_back(coatfft::parse_method(name));
    if (!grids.empty()) cfg.grids = grids;
    return sweep_main(cfg);
  } catch (const std::exception& e) {
    std::cerr << "bench_sweep: " << e.what() << "\n";
    return 1;
  }
}
