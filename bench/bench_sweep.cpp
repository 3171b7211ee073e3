// Speed against error (issue 5): sweeps method x grid x alpha x g(0) choice on Hertz loads over
// homogeneous and coated half-spaces and writes one CSV row per setting, with "# key = value"
// headers (machine, compiler, flags, FFTW version, threads, date). Errors are in the seed paper's
// measure (Spinu 2021, Fig. 2): (u - u_ref) / u_ref(0), max and RMS over the grid's cells.
//
// Every row runs in a child process (this program re-executed with --row), so that the peak
// resident set size of the row is the child's own (wait4's rusage), not the high-water mark of
// the sweep; the child writes its displacement to a temporary file and the parent, which holds the
// reference field, computes the errors.
//
// Usage: bench_sweep [--tiny | --quick | --full] [--output PATH] [--threads T]
//                    [--planning estimate|measure] [--cases c1,c2] [--methods m1,m2]
//                    [--grids N1,N2]
//        bench_sweep --figures DIR [--tiny]   small CSVs for the seed's Figures 2 and 3
//        bench_sweep --check-reference [--output PATH]  convergence of the references
//        bench_sweep --peak-rss CMD [ARGS...]  runs CMD and prints its peak RSS [MB]
//        bench_sweep --row ...                 (internal: one row, in the child)
#include <fftw3.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/sweep_cases.hpp"
#include "convolution/dcfft_operator.hpp"
#include "convolution/direct_operator.hpp"
#include "convolution/frf_dcfft_operator.hpp"
#include "convolution/frf_influence_kernel.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "convolution/g0.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "validation/hankel_displacement.hpp"
#include "validation/hertz.hpp"

namespace {

namespace sweep = coatfft::sweep;
using coatfft::Field;
using coatfft::Grid;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------------
// Settings of one row.

struct RowSpec {
  std::string case_name;
  std::string method;  // direct, dcfft, frf-spectral, frf-dcfft, frf-split
  std::ptrdiff_t n = 0;
  double alpha = 0.0;       // 0: not applicable
  std::string g0 = "none";  // none, regularized, quadrature
  double g0_tol = 0.0;
};

coatfft::G0Method g0_method(const std::string& name) {
  if (name == "regularized") return coatfft::G0Method::regularized;
  COATFFT_REQUIRE(name == "quadrature", "bench_sweep: g0 = '", name,
                  "', expected regularized or quadrature");
  return coatfft::G0Method::quadrature;
}

coatfft::Planning planning_from(const std::string& name) {
  if (name == "measure") return coatfft::Planning::measure;
  COATFFT_REQUIRE(name == "estimate", "bench_sweep: planning = '", name,
                  "', expected estimate or measure");
  return coatfft::Planning::estimate;
}

// ---------------------------------------------------------------------------------------------
// The child: build the operator (timed as setup), apply it (timed), write u.

struct RowTiming {
  double setup_s = 0.0;
  double coeff_s = 0.0;
  double apply_s_median = 0.0;
  int reps = 0;
};

// One warm-up application (its result is kept), then repeated ones for about `budget_s`
// seconds (3 to 51 of them); the median is robust to other processes sharing the machine.
RowTiming time_applications(coatfft::SurfaceOperator& op, const Field& p, Field& u,
                            double budget_s) {
  const auto t0 = Clock::now();
  op.apply(p, u);
  const double once = seconds_since(t0);
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 3, 51);
  std::vector<double> s;
  Field scratch;
  for (int r = 0; r < reps; ++r) {
    const auto t = Clock::now();
    op.apply(p, scratch);
    s.push_back(seconds_since(t));
  }
  std::sort(s.begin(), s.end());
  RowTiming timing;
  timing.apply_s_median = s[s.size() / 2];
  timing.reps = reps;
  return timing;
}

// Builds the row's operator; `coeff_s` receives the wall time [s] of the influence coefficients
// alone (Love, FRF -> IFFT, or split), 0 for frf-spectral, which has none.
std::unique_ptr<coatfft::SurfaceOperator> build_operator(const RowSpec& row,
                                                         const sweep::SweepCase& c,
                                                         const Grid& grid,
                                                         coatfft::Planning planning, int threads,
                                                         double& coeff_s) {
  const auto frf = coatfft::make_frf(c.stack);
  coeff_s = 0.0;
  if (row.method == "frf-spectral")
    return std::make_unique<coatfft::FrfSpectralOperator>(grid, *frf, row.alpha, g0_method(row.g0),
                                                          row.g0_tol, planning, threads);
  const auto t0 = Clock::now();
  if (row.method == "frf-dcfft") {
    // The coefficients are the part of the setup outside DcfftOperator's own constructor (at
    // alpha = 2 the FRF samples are the kernel's spectrum: no coefficients are formed).
    auto op = coatfft::frf_dcfft_operator(grid, *frf, row.alpha, g0_method(row.g0), row.g0_tol,
                                          nullptr, planning, threads);
    coeff_s = seconds_since(t0) - op->setup_seconds();
    return op;
  }
  if (row.method == "direct" || row.method == "dcfft") {
    COATFFT_REQUIRE(c.stack.is_homogeneous(), "bench_sweep: ", row.method,
                    " needs a homogeneous body");
    const coatfft::EvenInfluenceKernel quarter =
        coatfft::love_kernel_quarter(grid, c.stack.substrate().plane_strain_modulus());
    coeff_s = seconds_since(t0);
    if (row.method == "direct")
      return std::make_unique<coatfft::DirectOperator>(coatfft::wrap_even_kernel(quarter));
    return std::make_unique<coatfft::DcfftOperator>(quarter, planning, threads);
  }
  if (row.method != "frf-split")
    throw coatfft::InvalidArgument("bench_sweep: unknown method '" + row.method + "'");
  const coatfft::EvenInfluenceKernel kernel = coatfft::split_frf_kernel_quarter(grid, *frf);
  coeff_s = seconds_since(t0);
  return std::make_unique<coatfft::DcfftOperator>(kernel, planning, threads);
}

struct RowResult {
  RowTiming timing;
  Field u;
};

RowResult run_row(const RowSpec& row, coatfft::Planning planning, int threads, double budget_s) {
  const sweep::SweepCase c = sweep::find_case(row.case_name);
  const Grid grid = sweep::case_grid(c, row.n);
  const Field p = coatfft::hertz_pressure(grid, c.p0, c.a, c.sampling);
  const auto t0 = Clock::now();
  double coeff_s = 0.0;
  auto op = build_operator(row, c, grid, planning, threads, coeff_s);
  const double setup_s = seconds_since(t0);
  RowResult result;
  result.timing = time_applications(*op, p, result.u, budget_s);
  result.timing.setup_s = setup_s;
  result.timing.coeff_s = coeff_s;
  return result;
}

// Child entry: --row CASE METHOD N ALPHA G0 TOL PLANNING THREADS BUDGET UFILE. Writes nx*ny
// doubles (x fastest) to UFILE and "setup_s apply_s reps coeff_s" to UFILE.txt.
int row_main(const std::vector<std::string>& a) {
  COATFFT_REQUIRE(a.size() == 10, "bench_sweep --row: expected 10 arguments, got ", a.size());
  RowSpec row{a[0], a[1], std::stol(a[2]), std::stod(a[3]), a[4], std::stod(a[5])};
  const RowResult r = run_row(row, planning_from(a[6]), std::stoi(a[7]), std::stod(a[8]));
  {
    std::ofstream out(a[9], std::ios::binary);
    out.write(reinterpret_cast<const char*>(r.u.data()),
              static_cast<std::streamsize>(r.u.size() * sizeof(double)));
    COATFFT_REQUIRE(out.good(), "bench_sweep --row: cannot write ", a[9]);
  }
  std::ofstream txt(a[9] + ".txt");
  txt << std::setprecision(17) << r.timing.setup_s << ' ' << r.timing.apply_s_median << ' '
      << r.timing.reps << ' ' << r.timing.coeff_s << '\n';
  return txt.good() ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// The parent: fork/exec a child per row and collect its rusage.

std::string self_exe() {
  return std::filesystem::read_symlink("/proc/self/exe").string();
}

struct ChildOutcome {
  int exit_code = -1;
  double peak_rss_mb = 0.0;
  double wall_s = 0.0;
};

// Runs argv[0] with argv (no shell) and waits for it; wait4 returns the child's own rusage, whose
// ru_maxrss [KiB on Linux] is the child's peak resident set size.
ChildOutcome run_child(const std::vector<std::string>& argv) {
  std::vector<char*> cargv;
  for (const std::string& s : argv) cargv.push_back(const_cast<char*>(s.c_str()));
  cargv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const auto t0 = Clock::now();
  const pid_t pid = fork();
  COATFFT_REQUIRE(pid >= 0, "bench_sweep: fork failed");
  if (pid == 0) {
    execv(cargv[0], cargv.data());
    std::perror("bench_sweep: execv");
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  const pid_t waited = wait4(pid, &status, 0, &usage);
  COATFFT_REQUIRE(waited == pid, "bench_sweep: wait4 failed for pid ", pid);
  ChildOutcome out;
  out.wall_s = seconds_since(t0);
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  out.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return out;
}

int peak_rss_main(const std::vector<std::string>& cmd) {
  COATFFT_REQUIRE(!cmd.empty(), "bench_sweep --peak-rss: no command given");
  std::vector<std::string> argv = cmd;
  if (argv[0].find('/') == std::string::npos) {
    // execv does not search PATH; resolve the name the way a shell would.
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':'))
      if (std::filesystem::exists(dir + "/" + argv[0])) {
        argv[0] = dir + "/" + argv[0];
        break;
      }
  }
  const ChildOutcome out = run_child(argv);
  std::cout << "peak_rss_mb = " << out.peak_rss_mb << "\nwall_s = " << out.wall_s
            << "\nexit_code = " << out.exit_code << "\n";
  return out.exit_code;
}

// ---------------------------------------------------------------------------------------------
// Sweep plan.

struct SweepConfig {
  std::string mode = "full";
  std::string output;
  int threads = 1;
  std::string planning = "estimate";
  std::vector<std::string> cases;    // empty: all of the mode
  std::vector<std::string> methods;  // empty: all
  double budget_s = 0.5;
  std::vector<std::ptrdiff_t> grids;
  std::vector<double> alphas;
  std::vector<std::pair<std::string, double>> g0s;
  std::ptrdiff_t direct_max_n = 64;
  std::ptrdiff_t max_extended = 4096;   // cap on M = alpha N per axis (memory and time)
  std::ptrdiff_t quadrature_max_n = 0;  // g(0) by quadrature only up to this N (0: all)
};

SweepConfig mode_config(const std::string& mode) {
  SweepConfig cfg;
  cfg.mode = mode;
  const double regularized_tol = coatfft::default_g0_tolerance;
  cfg.g0s = {{"regularized", regularized_tol}, {"quadrature", 1e-4}, {"quadrature", 1e-8}};
  cfg.alphas = {2.0, 4.0, 8.0};
  if (mode == "tiny") {
    cfg.grids = {32, 64};
    cfg.alphas = {2.0, 4.0};
    cfg.g0s = {{"regularized", regularized_tol}, {"quadrature", 1e-4}};
    cfg.budget_s = 0.02;
    cfg.cases = {"hertz_homogeneous"};
  } else if (mode == "quick") {
    cfg.grids = {32, 64, 128, 256, 512};
    cfg.budget_s = 0.1;
  } else {
    COATFFT_REQUIRE(mode == "full", "bench_sweep: unknown mode '", mode, "'");
    cfg.grids = {32, 64, 128, 256, 512, 1024, 2048};
    cfg.budget_s = 0.3;
    cfg.direct_max_n = 128;
    // g(0) depends on alpha L only, not on N, so the quadrature variants shift u by the same
    // constant at every N: running them up to 256^2 shows their effect and saves minutes.
    cfg.quadrature_max_n = 256;
  }
  return cfg;
}

bool selected(const std::vector<std::string>& list, const std::string& name) {
  return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
}

std::vector<RowSpec> plan_rows(const SweepConfig& cfg, const sweep::SweepCase& c,
                               std::ptrdiff_t n) {
  std::vector<RowSpec> rows;
  const bool homogeneous = c.stack.is_homogeneous();
  if (homogeneous && n <= cfg.direct_max_n && selected(cfg.methods, "direct"))
    rows.push_back({c.name, "direct", n, 0.0, "none", 0.0});
  if (homogeneous && selected(cfg.methods, "dcfft"))
    rows.push_back({c.name, "dcfft", n, 0.0, "none", 0.0});
  if (selected(cfg.methods, "frf-split"))
    rows.push_back({c.name, "frf-split", n, 0.0, "none", 0.0});
  for (const std::string method : {"frf-spectral", "frf-dcfft"}) {
    if (!selected(cfg.methods, method)) continue;
    for (double alpha : cfg.alphas) {
      if (alpha * static_cast<double>(n) > static_cast<double>(cfg.max_extended)) continue;
      for (const auto& [g0, tol] : cfg.g0s) {
        if (g0 == "quadrature" && cfg.quadrature_max_n > 0 && n > cfg.quadrature_max_n) continue;
        rows.push_back({c.name, method, n, alpha, g0, tol});
      }
    }
  }
  return rows;
}

std::string fmt(double v) {
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

Field read_field(const std::string& path, std::ptrdiff_t n) {
  Field u(n, n);
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(u.data()), static_cast<std::streamsize>(u.size() * 8));
  COATFFT_REQUIRE(in.good(), "bench_sweep: cannot read the child's field from ", path);
  return u;
}

int sweep_main(const SweepConfig& cfg) {
  const auto t_start = Clock::now();
  std::ostringstream header;
  header << "# bench = bench_sweep (issue 5: speed against error)\n"
         << "# mode = " << cfg.mode << "\n";
  coatfft::bench::write_machine_header(header);
  header << "# threads = " << cfg.threads << "\n"
         << "# planning = " << cfg.planning << "\n"
         << "# load = Hertz p0 = 1 GPa, a = 1 mm on [-1.5a, 1.5a]^2 (N x N cells)\n"
         << "# error = (u - u_ref) / u_ref(0): max_err = max |.|, rms_err = RMS over all cells\n"
         << "# setup_s = wall time of building the operator (coefficients or FRF samples, g(0), "
            "kernel transform, FFTW plans)\n"
         << "# coeff_s = the part of setup_s spent on the influence coefficients (Love, FRF -> "
            "IFFT, split); 0 for frf-spectral\n"
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
  std::cout << header.str() << std::flush;

  std::filesystem::path out_path(cfg.output);
  if (out_path.has_parent_path()) std::filesystem::create_directories(out_path.parent_path());
  std::ofstream out(cfg.output);
  COATFFT_REQUIRE(out.good(), "bench_sweep: cannot write ", cfg.output);
  out << header.str() << std::flush;

  const std::string exe = self_exe();
  const std::string tmp =
      (std::filesystem::temp_directory_path() / ("bench_sweep_" + std::to_string(getpid())))
          .string();
  int failures = 0;
  for (const sweep::SweepCase& c : sweep::all_cases()) {
    if (!selected(cfg.cases, c.name)) continue;
    const auto t_table = Clock::now();
    const sweep::RadialReference u_ref(c, sweep::max_radius(c));
    std::cerr << "[" << fmt(seconds_since(t_start)) << " s] " << c.name << ": radial reference ("
              << u_ref.nb_nodes() << " nodes) in " << fmt(seconds_since(t_table)) << " s\n";
    for (std::ptrdiff_t n : cfg.grids) {
      const std::vector<RowSpec> rows = plan_rows(cfg, c, n);
      if (rows.empty()) continue;
      const auto t_ref = Clock::now();
      const sweep::Reference ref = sweep::reference(u_ref, sweep::case_grid(c, n));
      std::cerr << "[" << fmt(seconds_since(t_start)) << " s] " << c.name << " N = " << n
                << ": reference in " << fmt(seconds_since(t_ref)) << " s\n";
      for (const RowSpec& row : rows) {
        const std::vector<std::string> argv = {exe,
                                               "--row",
                                               row.case_name,
                                               row.method,
                                               std::to_string(row.n),
                                               fmt(row.alpha),
                                               row.g0,
                                               fmt(row.g0_tol),
                                               cfg.planning,
                                               std::to_string(cfg.threads),
                                               fmt(cfg.budget_s),
                                               tmp};
        const ChildOutcome child = run_child(argv);
        if (child.exit_code != 0) {
          ++failures;
          const std::string line = "# failed: " + row.case_name + "," + row.method + "," +
                                   std::to_string(n) + "," + fmt(row.alpha) + "," + row.g0 +
                                   " (exit code " + std::to_string(child.exit_code) + ")\n";
          std::cout << line;
          out << line << std::flush;
          continue;
        }
        const Field u = read_field(tmp, n);
        std::ifstream txt(tmp + ".txt");
        RowTiming timing;
        txt >> timing.setup_s >> timing.apply_s_median >> timing.reps >> timing.coeff_s;
        const Field diff = (u - ref.u) / ref.u_centre;
        const double max_err = diff.abs().maxCoeff();
        const double rms_err = std::sqrt(diff.square().mean());
        COATFFT_REQUIRE(std::isfinite(max_err) && std::isfinite(rms_err),
                        "bench_sweep: non-finite error for ", row.method, " N = ", n);
        std::ostringstream line;
        line << row.case_name << ',' << row.method << ',' << n << ',' << fmt(row.alpha) << ','
             << row.g0 << ',' << fmt(row.g0_tol) << ',' << sweep::to_string(c.sampling) << ','
             << fmt(timing.setup_s) << ',' << fmt(timing.apply_s_median) << ','
             << fmt(child.peak_rss_mb) << ',' << fmt(max_err) << ',' << fmt(rms_err) << ','
             << fmt(timing.coeff_s) << '\n';
        std::cout << line.str() << std::flush;
        out << line.str() << std::flush;
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

// ---------------------------------------------------------------------------------------------
// Seed figures: small CSVs, homogeneous Hertz, centre sampling (as in the seed).

// Writes the error (u - u_exact)/u_exact(0) of `u` along the row of cells through y = 0 (odd n).
void error_along_x(const Field& u, const Grid& grid, const Field& exact, double u0,
                   std::vector<double>& x_over_a, std::vector<double>& err, double a) {
  const std::ptrdiff_t j = grid.ny() / 2;
  x_over_a.clear();
  err.clear();
  for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
    x_over_a.push_back(grid.x(i) / a);
    err.push_back((u(i, j) - exact(i, j)) / u0);
  }
}

int figures_main(const std::string& dir, bool tiny) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const sweep::SweepCase c = sweep::find_case("hertz_homogeneous");
  const double e_star = c.stack.substrate().plane_strain_modulus();
  const auto frf = coatfft::make_frf(c.stack);
  const std::string sig =
      "# fig data from bench_sweep --figures; error = (u - u_exact)/u_exact(0)\n";

  // Figure 2(a): DC-FFT error field at N = 64.
  {
    const std::ptrdiff_t n = 64;
    const Grid grid = sweep::case_grid(c, n);
    const sweep::Reference ref = sweep::reference(c, grid);
    const Field p = coatfft::hertz_pressure(grid, c.p0, c.a, coatfft::Sampling::centre);
    coatfft::DcfftOperator op(coatfft::love_kernel(grid, e_star));
    const Field u = op.apply(p);
    std::ofstream f(dir + "/fig2a_dcfft_error_field.csv");
    f << sig << "# N = " << n << "\nx_over_a,y_over_a,err\n" << std::setprecision(8);
    for (std::ptrdiff_t j = 0; j < n; ++j)
      for (std::ptrdiff_t i = 0; i < n; ++i)
        f << grid.x(i) / c.a << ',' << grid.y(j) / c.a << ','
          << (u(i, j) - ref.u(i, j)) / ref.u_centre << '\n';
  }
  // Figure 2(b): DC-FFT max error against N.
  {
    std::ofstream f(dir + "/fig2b_dcfft_error_vs_n.csv");
    f << sig << "N,max_err,rms_err\n" << std::setprecision(8);
    const std::vector<std::ptrdiff_t> ns =
        tiny ? std::vector<std::ptrdiff_t>{16, 32, 64}
             : std::vector<std::ptrdiff_t>{16, 32, 64, 128, 256, 512, 1024, 2048};
    for (std::ptrdiff_t n : ns) {
      const Grid grid = sweep::case_grid(c, n);
      const sweep::Reference ref = sweep::reference(c, grid);
      const Field p = coatfft::hertz_pressure(grid, c.p0, c.a, coatfft::Sampling::centre);
      coatfft::DcfftOperator op(coatfft::love_kernel(grid, e_star));
      const Field d = (op.apply(p) - ref.u) / ref.u_centre;
      f << n << ',' << d.abs().maxCoeff() << ',' << std::sqrt(d.square().mean()) << '\n';
    }
  }
  // Figure 3: FRF pipelines along the x axis, N = 65 (a row of cells lies on y = 0).
  const std::ptrdiff_t n3 = 65;
  const Grid grid = sweep::case_grid(c, n3);
  const sweep::Reference ref = sweep::reference(c, grid);
  const Field p = coatfft::hertz_pressure(grid, c.p0, c.a, coatfft::Sampling::centre);
  std::vector<double> xs, err;
  {
    std::ofstream f(dir + "/fig3a_frf_alpha.csv");
    f << sig << "# N = " << n3 << ", g0 = regularized, row y = 0\nmethod,alpha,x_over_a,err\n"
      << std::setprecision(8);
    for (double alpha : {2.0, 4.0, 8.0, 12.0}) {
      coatfft::FrfSpectralOperator spectral(grid, *frf, alpha, coatfft::G0Method::regularized);
      error_along_x(spectral.apply(p), grid, ref.u, ref.u_centre, xs, err, c.a);
      for (std::size_t i = 0; i < xs.size(); ++i)
        f << "frf-spectral," << alpha << ',' << xs[i] << ',' << err[i] << '\n';
      coatfft::DcfftOperator dc(
          coatfft::frf_influence_kernel(grid, *frf, alpha, coatfft::G0Method::regularized));
      error_along_x(dc.apply(p), grid, ref.u, ref.u_centre, xs, err, c.a);
      for (std::size_t i = 0; i < xs.size(); ++i)
        f << "frf-dcfft," << alpha << ',' << xs[i] << ',' << err[i] << '\n';
    }
  }
  {
    std::ofstream f(dir + "/fig3b_frf_g0.csv");
    f << sig << "# N = " << n3 << ", alpha = 2, frf-spectral, row y = 0\n"
      << "g0,g0_tol,g0_value,g0_seconds,x_over_a,err\n"
      << std::setprecision(10);
    const double alpha = 2.0;
    const double dk = 2.0 * M_PI / (alpha * grid.lx());
    std::vector<std::pair<std::string, double>> choices = {{"regularized", 1e-13}};
    for (double tol : {1e-1, 1e-2, 1e-4, 1e-6, 1e-8}) choices.emplace_back("quadrature", tol);
    for (const auto& [name, tol] : choices) {
      const coatfft::G0Result g0 = coatfft::compute_g0(*frf, dk, dk, g0_method(name), tol);
      coatfft::FrfSpectralOperator spectral(grid, *frf, alpha, g0);
      error_along_x(spectral.apply(p), grid, ref.u, ref.u_centre, xs, err, c.a);
      for (std::size_t i = 0; i < xs.size(); ++i)
        f << name << ',' << tol << ',' << g0.value << ',' << g0.seconds << ',' << xs[i] << ','
          << err[i] << '\n';
    }
  }
  std::cerr << "figure data written to " << dir << "\n";
  return 0;
}

// How converged the references are: the Hankel reference used (split route, rel_tol 1e-10)
// against a tighter one (1e-13) and against the independent direct route (no closed-form part),
// the interpolated table of RadialReference against fresh evaluations between its nodes, and for
// the homogeneous case the Hankel value against the closed form; 97 radii in [0, r_max].
int check_reference_main(const std::string& output) {
  std::ostringstream os;
  os << "# bench_sweep --check-reference: max differences / u_ref(0) over 97 radii in [0, "
        "1.5 sqrt(2) a], node-straddling\n"
     << "case,u_ref0_m,table_nodes,table_dr_over_a,table_s,eval_ms,diff_tol_1e-13,"
        "diff_direct_route,diff_table_interpolation,diff_closed_form\n";
  for (const sweep::SweepCase& c : sweep::all_cases()) {
    const auto t_table = Clock::now();
    const sweep::RadialReference u_ref(c, sweep::max_radius(c));
    const double table_s = seconds_since(t_table);
    const double u0 = u_ref(0.0);
    double d_tight = 0.0, d_direct = 0.0, d_table = 0.0, d_closed = 0.0, eval_s = 0.0;
    const int count = 97;
    for (int q = 0; q < count; ++q) {
      // Irrational steps put the radii between the table's nodes.
      const double r = sweep::max_radius(c) * (q + 0.5 * M_SQRT1_2) / count;
      const auto t0 = Clock::now();
      const double u = u_ref.exact(r);
      eval_s += seconds_since(t0);
      d_tight = std::max(d_tight, std::abs(u - u_ref.exact(r, 1e-13)) / u0);
      d_direct = std::max(d_direct, std::abs(u - u_ref.exact(r, sweep::reference_tolerance,
                                                             coatfft::HankelRoute::direct)) /
                                        u0);
      d_table = std::max(d_table, std::abs(u - u_ref(r)) / u0);
      if (c.stack.is_homogeneous())
        d_closed = std::max(
            d_closed, std::abs(u - coatfft::hertz_displacement(
                                       r, c.p0, c.a, c.stack.substrate().plane_strain_modulus())) /
                          u0);
    }
    os << c.name << ',' << fmt(u0) << ',' << u_ref.nb_nodes() << ','
       << fmt(u_ref.node_spacing() / c.a) << ',' << fmt(table_s) << ',' << fmt(1e3 * eval_s / count)
       << ',' << fmt(d_tight) << ',' << fmt(d_direct) << ',' << fmt(d_table) << ','
       << (c.stack.is_homogeneous() ? fmt(d_closed) : "n/a") << '\n';
  }
  std::cout << os.str();
  if (!output.empty()) coatfft::bench::write_text_file(output, os.str());
  return 0;
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "--row")
      return row_main(std::vector<std::string>(args.begin() + 1, args.end()));
    if (!args.empty() && args[0] == "--peak-rss")
      return peak_rss_main(std::vector<std::string>(args.begin() + 1, args.end()));

    std::string mode = "full";
    std::optional<std::string> output, threads, planning, cases, methods, figures, grids;
    bool check_reference = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      auto value = [&](std::optional<std::string>& slot) {
        COATFFT_REQUIRE(i + 1 < args.size(), "bench_sweep: ", a, " needs a value");
        slot = args[++i];
      };
      if (a == "--tiny" || a == "--quick" || a == "--full")
        mode = a.substr(2);
      else if (a == "--output")
        value(output);
      else if (a == "--threads")
        value(threads);
      else if (a == "--planning")
        value(planning);
      else if (a == "--cases")
        value(cases);
      else if (a == "--methods")
        value(methods);
      else if (a == "--grids")
        value(grids);
      else if (a == "--figures")
        value(figures);
      else if (a == "--check-reference")
        check_reference = true;
      else
        throw coatfft::InvalidArgument("bench_sweep: unknown argument '" + a +
                                       "' (see the usage at the top of bench_sweep.cpp)");
    }
    if (figures) return figures_main(*figures, mode == "tiny");
    if (check_reference) return check_reference_main(output ? *output : "");
    SweepConfig cfg = mode_config(mode);
    cfg.output = output ? *output : std::string(COATFFT_SOURCE_DIR) + "/bench/results/sweep.csv";
    if (threads) cfg.threads = std::stoi(*threads);
    COATFFT_REQUIRE(cfg.threads >= 1, "bench_sweep: threads = ", cfg.threads, ", must be >= 1");
    if (planning) cfg.planning = *planning;
    planning_from(cfg.planning);
    if (cases) cfg.cases = split_list(*cases);
    if (methods) cfg.methods = split_list(*methods);
    if (grids) {
      cfg.grids.clear();
      for (const std::string& g : split_list(*grids)) cfg.grids.push_back(std::stol(g));
      for (std::ptrdiff_t n : cfg.grids)
        COATFFT_REQUIRE(n >= 2, "bench_sweep: grid N = ", n, ", must be >= 2");
    }
    return sweep_main(cfg);
  } catch (const std::exception& e) {
    std::cerr << "bench_sweep: " << e.what() << "\n";
    return 1;
  }
}
