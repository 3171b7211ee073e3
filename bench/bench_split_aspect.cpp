// frf-split on elongated cells and domains, next to frf-spectral: the setup of frf-split must be
// bounded by the grid size, not by the aspect ratio of the cells or of the domain. The body is TiN
// (400 GPa, 0.25) 20 um bonded on steel (210 GPa, 0.3) under a Hertz pressure (p0 = 1 GPa,
// a = 0.5 mm, cell-averaged), the cases those of docs/split_kernel.md (section 7): 24 x 24
// cells on 2 mm x ly for ly = 2 mm .. 4096 m, and 1 x 4096 and 4096 x 1 cells on 2 mm x 2 mm.
// For each case and method: make_operator (setup, of which the influence kernel) and one
// application, medians of `reps` runs, and max |u| of the two methods. Prints "# key = value"
// headers and CSV rows and writes them to bench/results/split_aspect_ratio.csv (or OUTPUT).
//   bench_split_aspect [OUTPUT] [--reps 3] [--threads 1] [--cases ly_2mm,...,4096x1]
#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/method.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/grid.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using namespace coatfft;
using coatfft::detail::median;

struct Case {
  std::string name;
  std::ptrdiff_t nx;
  std::ptrdiff_t ny;
  double lx;
  double ly;
};

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases = {
      {"ly_2mm", 24, 24, 2e-3, 2e-3},     {"ly_20mm", 24, 24, 2e-3, 20e-3},
      {"ly_200mm", 24, 24, 2e-3, 0.2},    {"ly_0.4m", 24, 24, 2e-3, 0.4},
      {"ly_4096m", 24, 24, 2e-3, 4096.0}, {"1x4096", 1, 4096, 2e-3, 2e-3},
      {"4096x1", 4096, 1, 2e-3, 2e-3}};
  return cases;
}

struct Timing {
  double kernel_s = 0.0;
  double setup_s = 0.0;
  double apply_s = 0.0;
  double u_max = 0.0;
  OperatorReport report;
};

// Medians over `reps` builds of the operator, one application after each.
Timing time_method(const Grid& grid, const LayerStack& body, const Field& p, Method method,
                   int threads, int reps) {
  OperatorOptions options;
  options.method = method;
  options.threads = threads;
  std::vector<double> kernel_s, setup_s, apply_s;
  Timing t;
  Field u;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    BuiltOperator built = make_operator(grid, body, options);
    setup_s.push_back(detail::seconds_since(start));
    kernel_s.push_back(built.report.kernel_seconds);
    apply_s.push_back(detail::time_applications(*built.op, p, u, 1));
    t.report = built.report;
  }
  t.kernel_s = median(kernel_s);
  t.setup_s = median(setup_s);
  t.apply_s = median(apply_s);
  t.u_max = u.abs().maxCoeff();
  return t;
}

// What the split kernel chose: sigma, wide axes, alias order, Hankel radii, cell rule.
std::string split_columns(const OperatorReport& report) {
  std::ostringstream os;
  if (!report.split) return ",,,,";
  const SplitKernelReport& s = *report.split;
  os << s.sigma << ',' << (s.wide_x ? "x" : "") << (s.wide_y ? "y" : "") << ',' << s.alias_order
     << (s.alias_capped ? " (capped)" : "") << ',' << s.hankel_r_points << ',' << s.cell_rule;
  return os.str();
}

std::string header(int reps, int threads) {
  std::ostringstream csv;
  csv << "# bench_split_aspect: frf-split against frf-spectral on elongated cells and domains, "
         "setup (make_operator) and one application, medians\n";
  bench::write_machine_header(csv);
  csv << "# planning = FFTW_ESTIMATE, alpha = 2 (frf-spectral), g0 = regularized\n";
  csv << "# body = TiN (400 GPa, 0.25) 20 um bonded on steel (210 GPa, 0.3); Hertz p0 = 1 GPa, "
         "a = 0.5 mm, cell-averaged\n";
  csv << "# reps = " << reps << ", threads = " << threads << "\n";
  csv << "case,nx,ny,lx,ly,method,kernel_s,setup_s,apply_s,total_s,u_max,sigma,wide,"
         "alias_order,hankel_radii,cell_rule\n";
  return csv.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"frf-split on elongated cells and domains, next to frf-spectral"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/split_aspect_ratio.csv";
  app.add("output", out_path, "CSV file").show_default();
  int reps = 3;
  app.add("--reps", reps, "Builds per case and method").show_default().positive();
  int threads = 1;
  app.add("--threads", threads, "Threads of the setup and the application")
      .show_default()
      .positive();
  std::vector<std::string> names;
  app.add("--cases", names, "Cases (default: all)").comma_separated();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    const LayerStack body({Coating{Material(400e9, 0.25), 20e-6, Interface::bonded}},
                          Material(210e9, 0.3));
    std::ostringstream csv;
    csv << header(reps, threads);
    std::cout << csv.str() << std::flush;
    for (const Case& c : all_cases()) {
      if (!names.empty() && std::find(names.begin(), names.end(), c.name) == names.end()) continue;
      const Grid grid(c.nx, c.ny, c.lx, c.ly);
      const Field p = hertz_pressure(grid, 1e9, 0.5e-3, Sampling::cell_average);
      for (const Method m : {Method::frf_split, Method::frf_spectral}) {
        const Timing t = time_method(grid, body, p, m, threads, reps);
        std::ostringstream row;
        row << c.name << ',' << c.nx << ',' << c.ny << ',' << c.lx << ',' << c.ly << ','
            << to_string(m) << ',' << t.kernel_s << ',' << t.setup_s << ',' << t.apply_s << ','
            << t.setup_s + t.apply_s << ',' << t.u_max << ',' << split_columns(t.report) << '\n';
        std::cout << row.str() << std::flush;
        csv << row.str();
      }
    }
    bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_split_aspect: " << e.what() << '\n';
    return 1;
  }
}
