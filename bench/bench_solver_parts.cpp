// Where a contact iteration goes: the solver of ContactSolver on the rough surfaces of
// bench/rough_gap.hpp (H = 0.8, rms slope 0.05, shortest wavelength 16 cells), pressed into
// steel and into TiN-coated steel (5 um) on periodic grids, load control at about 10 % contact
// area, tolerance 1e-10, one thread; each problem solved twice, side by side: `before`
// (Polonsky & Keer's conjugation from the Hertzian start, the solver as it was) and `after`
// (the defaults: Polak-Ribiere's conjugation from the nested start). For each: iterations,
// applications (and those on the coarser grids) and the solve's time; one application timed
// alone; the FFT floor (a bare FFTW r2c, multiply, c2r pair of the same size, planned with
// FFTW_MEASURE) measured in the same run; and the solve's time split into its parts
// (ContactTimings) in units of one application: the steps' applications, the recomputations
// after a change of the contact set, the preconditioner's transforms, the element-wise passes
// and the start; and the periodic influence kernel's construction (the operator's set-up, one
// thread) against the solve. Ends with the exponent of iterations against N (least squares on
// log-log, per body and solver). Writes bench/results/solver_parts.csv (or OUTPUT).
//   bench_solver_parts [OUTPUT] [--sizes N ...]
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "bench/rough_gap.hpp"
#include "contact/contact_solver.hpp"
#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/fft/fftw_wisdom.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

const Material kSteel(210e9, 0.3);
constexpr double kLength = 1e-3;     // period [m]
constexpr double kLoad = 0.1 / 2.2;  // p_m / (E* g): about 10 % contact area on steel

struct Body {
  std::string label;
  LayerStack stack;
};

// Median wall time [ms] of five calls of `run` after one warm-up.
template <class Run>
double median_ms(Run&& run) {
  run();
  std::vector<double> times;
  for (int k = 0; k < 5; ++k) {
    const auto start = Clock::now();
    run();
    times.push_back(1e3 * detail::seconds_since(start));
  }
  return detail::median(times);
}

// The FFT floor of an n x n periodic application: r2c, a multiplication by a real spectrum,
// c2r, on FFTW_MEASURE plans, one thread.
double fft_floor_ms(std::ptrdiff_t n) {
  const auto n_real = static_cast<std::size_t>(n * n);
  const auto n_complex = static_cast<std::size_t>((n / 2 + 1) * n);
  FftwRealBuffer real(n_real);
  FftwComplexBuffer spectrum(n_complex);
  const int ni = static_cast<int>(n);
  const FftwPlan forward = FftwPlan::create(
      1, [&] { return fftw_plan_dft_r2c_2d(ni, ni, real.data(), spectrum.data(), FFTW_MEASURE); });
  const FftwPlan backward = FftwPlan::create(
      1, [&] { return fftw_plan_dft_c2r_2d(ni, ni, spectrum.data(), real.data(), FFTW_MEASURE); });
  std::vector<double> multiplier(n_complex, 0.5);
  for (std::size_t k = 0; k < n_real; ++k) real.data()[k] = 1e-6 * static_cast<double>(k % 97);
  return median_ms([&] {
    forward.execute();
    std::complex<double>* s = as_complex(spectrum.data());
    for (std::size_t q = 0; q < n_complex; ++q) s[q] *= multiplier[q];
    backward.execute();
  });
}

struct Solver {
  std::string label;
  ContactOptions options;
};

// The solver as it was (Polonsky & Keer's conjugation from the Hertzian start) and as it is.
std::vector<Solver> solvers() {
  ContactOptions before;
  before.conjugation = Conjugation::polonsky_keer;
  before.nested_start = false;
  return {{"before", before}, {"after", ContactOptions{}}};
}

// One row: the solve and its parts, in applications of `apply_ms`.
void solve_row(std::ptrdiff_t n, const Body& body, const Solver& s, PeriodicOperator& op,
               const Field& gap, double apply_ms, double floor_ms, double kernel_ms,
               std::map<std::string, std::vector<double>>& fit, std::ostream& out) {
  ContactSolver solver(op, s.options);
  const double load =
      kLoad * kSteel.plane_strain_modulus() * bench::rough_rms_slope * kLength * kLength;
  const ContactResult r = solver.solve_load(gap, load);
  const ContactTimings& t = r.timings;
  const double apply_s = 1e-3 * apply_ms, per_iteration = 1.0 / r.iterations;
  std::ostringstream row;
  row.precision(4);
  row << n << "," << body.label << "," << s.label << "," << r.iterations << ","
      << r.operator_applications << "," << r.coarse_applications << "," << (r.converged ? 1 : 0)
      << "," << r.contact_area / (kLength * kLength) << "," << 1e3 * t.total << "," << apply_ms
      << "," << floor_ms << "," << apply_ms / floor_ms << "," << 1e3 * t.total * per_iteration
      << "," << t.total * per_iteration / apply_s << "," << t.steps * per_iteration / apply_s << ","
      << t.recomputations * per_iteration / apply_s << ","
      << t.preconditioner * per_iteration / apply_s << "," << t.passes * per_iteration / apply_s
      << "," << t.start / apply_s << "," << kernel_ms << "," << kernel_ms / (1e3 * t.total) << "\n";
  std::cout << row.str() << std::flush;
  out << row.str();
  const std::string key = body.label + ", " + s.label;
  fit[key].push_back(std::log(static_cast<double>(n)));
  fit[key + " iterations"].push_back(std::log(static_cast<double>(r.iterations)));
}

// The slope of y against x by least squares.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Where a contact iteration goes, against the FFT floor"};
  std::string path = "bench/results/solver_parts.csv";
  app.add("output", path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512, 1024};
  app.add("--sizes", sizes, "grid sizes N (N x N cells)").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_solver_parts (periodic rough contact, load control, 1 thread)\n";
    bench::write_machine_header(out);
    out << "# surface = bench/rough_gap.hpp (H 0.8, rms slope " << bench::rough_rms_slope
        << ", shortest wavelength " << bench::rough_short_cutoff_cells
        << " cells); load p_m/(E* g) = " << kLoad << "; tolerance 1e-10; preconditioned\n"
        << "# apply_ms: one application alone (median of 5, FFTW_ESTIMATE plans as the solver's\n"
        << "#   default operator); floor_ms: bare r2c * multiply * c2r, FFTW_MEASURE, same run\n"
        << "# per_iteration_applications = solve time per iteration / apply_ms; its parts (steps,\n"
        << "#   recomputations, preconditioner, passes) likewise per iteration; "
           "start_applications\n"
        << "#   = the start's time (scaling, initial pressure) / apply_ms, once per solve\n"
        << "# kernel_ms: the periodic influence kernel's construction (one thread), the "
           "operator's\n"
        << "#   set-up; kernel_over_solve: over that row's solve\n"
        << "# coarse_applications: on the coarser grids of the nested start (a quarter of the\n"
        << "#   cells or fewer each), their time in start_applications\n"
        << "N,body,solver,iterations,applications,coarse_applications,converged,area_fraction,"
           "solve_ms,apply_ms,floor_ms,apply_over_floor,per_iteration_ms,"
           "per_iteration_applications,steps,recomputations,preconditioner,passes,"
           "start_applications,kernel_ms,kernel_over_solve\n";
    std::cout << out.str() << std::flush;
    const std::vector<Body> bodies = {
        {"steel", LayerStack(kSteel)},
        {"TiN 5 um on steel",
         LayerStack({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSteel)}};
    std::map<std::string, std::vector<double>> fit;
    for (const std::ptrdiff_t n : sizes) {
      const Grid g(n, n, kLength, kLength);
      const Field gap = bench::rough_gap(g);
      const double floor_ms = fft_floor_ms(n);
      // The floor's measured plans would answer the operator's FFTW_ESTIMATE ones from wisdom:
      // forgotten, so that the operator's plans are the estimate plans its rows say.
      forget_fftw_wisdom();
      for (const Body& body : bodies) {
        PeriodicKernelOptions o;
        const auto kernel_start = std::chrono::steady_clock::now();
        const Field kernel = periodic_influence_kernel(g, *make_frf(body.stack), o);
        const double kernel_ms = 1e3 * detail::seconds_since(kernel_start);
        PeriodicOperator op(g, kernel, exact_method(body.stack), Planning::estimate);
        Field u;
        const double apply_ms = median_ms([&] { op.apply(gap, u); });
        for (const Solver& s : solvers())
          solve_row(n, body, s, op, gap, apply_ms, floor_ms, kernel_ms, fit, out);
      }
    }
    std::ostringstream fits;
    for (const Body& body : bodies) {
      for (const Solver& s : solvers()) {
        const std::string key = body.label + ", " + s.label;
        if (fit[key].size() >= 2)
          fits << "# iterations ~ N^" << slope(fit[key], fit[key + " iterations"]) << " (" << key
               << ", least squares over the sizes above)\n";
      }
    }
    std::cout << fits.str() << std::flush;
    out << fits.str();
    bench::write_text_file(path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_solver_parts: " << e.what() << "\n";
    return 1;
  }
}
