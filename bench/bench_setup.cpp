// Setup cost against application cost (the setup should cost at most 3 applications at 1024^2 for
// every method). For each body, grid and method the setup is split into its parts (influence
// coefficients or FRF sampling, g(0), FFTW planning + kernel transform: bench/timed_setup.hpp) and
// timed `reps` times, interleaved with applications of the operator it built (so that the load of
// the shared machine hits both alike); medians are reported with the ratio setup / apply.
// FFTW_ESTIMATE throughout. Prints "# key = value" headers and CSV rows and writes them to
// bench/results/setup.csv (or OUTPUT).
//   bench_setup [OUTPUT] [--sizes 512,1024] [--threads 1,2] [--reps 5] [--alpha 2]
//               [--methods dcfft,frf-spectral,frf-dcfft,frf-split]
// (alpha is the extension ratio of frf-spectral and frf-dcfft; at alpha = 4 frf-dcfft's "kernel"
// is frf_influence_kernel: FRF sampling on the 4N lattice and its DCT-I.)
#include <cmath>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "bench/timed_setup.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/method.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using namespace coatfft;
using coatfft::detail::median;

struct Body {
  std::string name;
  LayerStack stack;
};

constexpr double length = 4e-3;  // domain side [m]
constexpr int applies_per_rep = 3;

// Hertz's pressure, p0 = 1 GPa on a = 1 mm, at the cell centres of `grid`.
Field hertz_field(const Grid& grid) {
  Field p(grid.nx(), grid.ny());
  for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
      const double r2 = (grid.x(i) * grid.x(i) + grid.y(j) * grid.y(j)) / 1e-6;
      p(i, j) = r2 < 1.0 ? 1e9 * std::sqrt(1.0 - r2) : 0.0;
    }
  return p;
}

// One CSV row: the medians of `reps` setups of `method` for `body` on `grid` and of the
// applications after each.
std::string measure_row(const Body& body, Method method, const Grid& grid, const Field& p,
                        int threads, double alpha, int reps) {
  OperatorOptions options;
  options.method = method;
  options.alpha = alpha;
  options.g0 = G0Method::regularized;
  options.g0_tolerance = default_g0_tolerance;
  options.threads = threads;
  std::vector<double> kernel_s, g0_s, transform_s, setup_s, apply_s;
  Field u;
  for (int r = 0; r < reps; ++r) {
    const bench::TimedSetup s = bench::timed_setup(grid, body.stack, options);
    kernel_s.push_back(s.kernel_s);
    g0_s.push_back(s.g0_s);
    transform_s.push_back(s.transform_s);
    setup_s.push_back(s.kernel_s + s.g0_s + s.transform_s);
    for (int a = 0; a < applies_per_rep; ++a)
      apply_s.push_back(detail::time_applications(*s.built.op, p, u, 1));
  }
  std::ostringstream row;
  const double st = median(setup_s);
  const double ap = median(apply_s);
  row << body.name << ',' << to_string(method) << ',' << grid.nx() << ',' << threads << ','
      << median(kernel_s) << ',' << median(g0_s) << ',' << median(transform_s) << ',' << st << ','
      << ap << ',' << st / ap << '\n';
  return row.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Setup against application cost per method"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/setup.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {512, 1024};
  app.add("--sizes", sizes, "Grid sizes N")
      .comma_separated()
      .show_default()
      .range(std::ptrdiff_t{2}, std::ptrdiff_t{1} << 16);
  std::vector<int> thread_list = {1, 2};
  app.add("--threads", thread_list, "Thread counts").comma_separated().show_default().positive();
  int reps = 5;
  app.add("--reps", reps, "Setups per row").show_default().positive();
  double alpha = 2.0;
  app.add("--alpha", alpha, "Extension ratio of frf-spectral and frf-dcfft").show_default();
  std::vector<std::string> method_names;
  app.add("--methods", method_names, "Methods (default: all but direct)").comma_separated();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::vector<Method> methods;
    for (const std::string& name : method_names) methods.push_back(parse_method(name));
    if (methods.empty())  // direct summation is O(N^4): not at these sizes
      for (const Method m : all_methods)
        if (m != Method::direct) methods.push_back(m);

    const Material steel(210e9, 0.3);
    const Material tin(600e9, 0.25);
    const std::vector<Body> bodies = {
        {"steel", LayerStack(steel)},
        {"tin50um_on_steel", LayerStack({Coating{tin, 50e-6, Interface::bonded}}, steel)}};

    std::ostringstream csv;
    csv << "# bench_setup: setup (coefficients/sampling + g0 + plans/kernel transform) vs one "
           "application, medians of interleaved runs\n";
    coatfft::bench::write_machine_header(csv);
    csv << "# planning = FFTW_ESTIMATE\n";
    csv << "# domain = " << length << " m square, alpha = " << alpha << "\n";
    csv << "# bodies = steel (E 210 GPa, nu 0.3); TiN (600 GPa, 0.25) 50 um bonded on steel\n";
    csv << "# reps = " << reps << " setups, " << applies_per_rep << " applications after each\n";
    csv << "body,method,n,threads,kernel_s,g0_s,transform_s,setup_s,apply_s,ratio\n";
    std::cout << csv.str() << std::flush;

    for (const std::ptrdiff_t n : sizes) {
      const Grid grid(n, n, length, length);
      const Field p = hertz_field(grid);
      for (const Body& body : bodies)
        for (const int threads : thread_list)
          for (const Method method : methods) {
            // Love's coefficients: homogeneous bodies only.
            if (uses_love_coefficients(method) && !body.stack.is_homogeneous()) continue;
            const std::string row = measure_row(body, method, grid, p, threads, alpha, reps);
            std::cout << row << std::flush;
            csv << row;
          }
    }
    coatfft::bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_setup: " << e.what() << '\n';
    return 1;
  }
}
