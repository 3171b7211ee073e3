// The data of Figures 2 and 3 of Spinu (2021), redrawn for coatfft: small CSVs on the homogeneous
// Hertz case of the sweep (bench/sweep_cases.hpp, centre sampling), which
// scripts/plot_spinu_figures.py plots into docs/figures:
//   fig2a_dcfft_error_field.csv  DC-FFT error field at N = 64;
//   fig2b_dcfft_error_vs_n.csv   DC-FFT max and RMS error against N;
//   fig3a_frf_alpha.csv          frf-spectral and frf-dcfft along y = 0 at N = 65, alpha 2 ... 12;
//   fig3b_frf_g0.csv             frf-spectral at alpha = 2 with g(0) by quadrature at several
//                                tolerances against the regularized g(0).
// bench_figures DIR [--tiny]   (--tiny: N up to 64 in fig2b)
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/command_line.hpp"
#include "bench/sweep_cases.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/operators/make_operator.hpp"
#include "loads/hertz_pressure.hpp"

namespace {

using namespace coatfft;

const char* const signature =
    "# data of the figures of Spinu (2021) from bench_figures; error = (u - u_exact)/u_exact(0)\n";

// The displacement of the homogeneous case on `grid` by `options`.
Field displacement(const sweep::SweepCase& c, const Grid& grid, const OperatorOptions& options) {
  const Field p = hertz_pressure(grid, c.p0, c.a, Sampling::centre);
  return make_operator(grid, c.stack, options).op->apply(p);
}

// Writes the error (u - u_exact)/u_exact(0) along the row of cells through y = 0 (odd n) as
// "<prefix>,x_over_a,err" lines.
void error_along_x(std::ostream& f, const std::string& prefix, const Field& u, const Grid& grid,
                   const sweep::Reference& ref, double a) {
  const std::ptrdiff_t j = grid.ny() / 2;
  for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
    f << prefix << grid.x(i) / a << ',' << (u(i, j) - ref.u(i, j)) / ref.u_centre << '\n';
}

// Figure 2: DC-FFT's error field at N = 64 (a) and its error against N (b).
void write_figure2(const std::string& dir, const sweep::SweepCase& c,
                   const OperatorOptions& options, bool tiny) {
  // Figure 2(a): DC-FFT error field at N = 64.
  {
    const std::ptrdiff_t n = 64;
    const Grid grid = sweep::case_grid(c, n);
    const sweep::Reference ref = sweep::reference(c, grid);
    const Field u = displacement(c, grid, options);
    std::ofstream f(dir + "/fig2a_dcfft_error_field.csv");
    f << signature << "# N = " << n << "\nx_over_a,y_over_a,err\n" << std::setprecision(8);
    for (std::ptrdiff_t j = 0; j < n; ++j)
      for (std::ptrdiff_t i = 0; i < n; ++i)
        f << grid.x(i) / c.a << ',' << grid.y(j) / c.a << ','
          << (u(i, j) - ref.u(i, j)) / ref.u_centre << '\n';
  }
  // Figure 2(b): DC-FFT max error against N.
  {
    std::ofstream f(dir + "/fig2b_dcfft_error_vs_n.csv");
    f << signature << "N,max_err,rms_err\n" << std::setprecision(8);
    const std::vector<std::ptrdiff_t> ns =
        tiny ? std::vector<std::ptrdiff_t>{16, 32, 64}
             : std::vector<std::ptrdiff_t>{16, 32, 64, 128, 256, 512, 1024, 2048};
    for (const std::ptrdiff_t n : ns) {
      const Grid grid = sweep::case_grid(c, n);
      const sweep::Reference ref = sweep::reference(c, grid);
      const Field d = (displacement(c, grid, options) - ref.u) / ref.u_centre;
      f << n << ',' << d.abs().maxCoeff() << ',' << std::sqrt(d.square().mean()) << '\n';
    }
  }
}

// Figure 3: the FRF pipelines' error along the x axis, N = 65 (a row of cells lies on y = 0),
// against alpha (a) and against g(0)'s computation (b).
void write_figure3(const std::string& dir, const sweep::SweepCase& c, OperatorOptions options) {
  const std::ptrdiff_t n3 = 65;
  const Grid grid = sweep::case_grid(c, n3);
  const sweep::Reference ref = sweep::reference(c, grid);
  {
    std::ofstream f(dir + "/fig3a_frf_alpha.csv");
    f << signature << "# N = " << n3 << ", g0 = regularized, row y = 0\nmethod,alpha,x_over_a,err\n"
      << std::setprecision(8);
    for (const double alpha : {2.0, 4.0, 8.0, 12.0})
      for (const Method method : {Method::frf_spectral, Method::frf_dcfft}) {
        std::ostringstream prefix;
        prefix << to_string(method) << ',' << alpha << ',';
        options.method = method;
        options.alpha = alpha;
        error_along_x(f, prefix.str(), displacement(c, grid, options), grid, ref, c.a);
      }
  }
  {
    std::ofstream f(dir + "/fig3b_frf_g0.csv");
    f << signature << "# N = " << n3 << ", alpha = 2, frf-spectral, row y = 0\n"
      << "g0,g0_tol,g0_value,g0_seconds,x_over_a,err\n"
      << std::setprecision(10);
    std::vector<std::pair<G0Method, double>> choices = {{G0Method::regularized, 1e-13}};
    for (const double tol : {1e-1, 1e-2, 1e-4, 1e-6, 1e-8})
      choices.emplace_back(G0Method::quadrature, tol);
    const Field p = hertz_pressure(grid, c.p0, c.a, Sampling::centre);
    options.method = Method::frf_spectral;
    options.alpha = 2.0;
    for (const auto& [g0, tol] : choices) {
      options.g0 = g0;
      options.g0_tolerance = tol;
      const BuiltOperator built = make_operator(grid, c.stack, options);
      std::ostringstream prefix;
      prefix << std::setprecision(10) << to_string(g0) << ',' << tol << ','
             << built.report.g0->value << ',' << built.report.g0->seconds << ',';
      error_along_x(f, prefix.str(), built.op->apply(p), grid, ref, c.a);
    }
  }
}

void write_figures(const std::string& dir, bool tiny) {
  std::filesystem::create_directories(dir);
  const sweep::SweepCase c = sweep::find_case("hertz_homogeneous");
  // g(0) regularized to 1e-13 unless said otherwise; the method and alpha are set per figure.
  OperatorOptions options;
  options.g0_tolerance = default_g0_tolerance;
  options.method = Method::dcfft;
  write_figure2(dir, c, options, tiny);
  write_figure3(dir, c, options);
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"The data of Figures 2 and 3 of Spinu (2021) for coatfft"};
  std::string dir;
  bool tiny = false;
  app.add("dir", dir, "Folder of the CSVs").required();
  app.flag("--tiny", tiny, "Grids up to N = 64 in Figure 2(b)");
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    write_figures(dir, tiny);
    std::cerr << "figure data written to " << dir << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_figures: " << e.what() << "\n";
    return 1;
  }
}
