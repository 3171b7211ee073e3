// Contact solver cost on a periodic rough surface: a self-affine surface (H = 0.8, rms slope 0.05,
// shortest wavelength 16 cells, roll-off at a quarter of the period) pressed by a rigid flat
// into steel and into TiN-coated steel (5 um), periodic boundaries, load control at a mean
// pressure that gives about 10 % contact area (A/A0 = kappa p_m/(E* g), kappa about 2.2 here),
// tolerance 1e-10. For each grid: the solver of one application per iteration and Polonsky &
// Keer's original (two), their applications and wall times, and one application timed alone;
// and (up to --single-up-to) the solver on single-precision FFTs at tolerances 1e-6, 1e-8 and
// 1e-10, with its pressure's error against the double solve.
// Prints `# key = value` headers and CSV rows, and writes the same to
// bench/results/rough_contact.csv (or OUTPUT).
//   bench_rough_contact [OUTPUT] [--sizes N ...] [--original-up-to N] [--single-up-to N]
#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "bench/rough_gap.hpp"
#include "contact/contact_solver.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

const Material kSteel(210e9, 0.3);
constexpr double kSlope = bench::rough_rms_slope;
constexpr double kLength = 1e-3;     // period [m]
constexpr double kLoad = 0.1 / 2.2;  // p_m / (E* g): about 10 % contact area on steel
constexpr int kShortCutoffCells = bench::rough_short_cutoff_cells;

struct Body {
  std::string label;
  LayerStack stack;
};

std::vector<Body> bodies() {
  return {{"steel", LayerStack(kSteel)},
          {"TiN 5 um on steel",
           LayerStack({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSteel)}};
}

double ms_since(Clock::time_point start) {
  return 1e3 * detail::seconds_since(start);
}

struct Variant {
  bool linearity;
  Precision precision;
  double tolerance;
};

// One solve; `reference` the pressure of the double-precision solve at 1e-10 (empty for that
// solve itself), against which a single-precision solve's error is measured.
ContactResult solve_row(std::ptrdiff_t n, const Body& body, PeriodicOperator& op, const Field& gap,
                        const Variant& v, double apply_ms, const Field* reference,
                        std::ostream& out) {
  ContactOptions opts;
  opts.update_by_linearity = v.linearity;
  opts.tolerance = v.tolerance;
  ContactSolver solver(op, opts);
  const double load = kLoad * kSteel.plane_strain_modulus() * kSlope * kLength * kLength;
  const auto start = Clock::now();
  ContactResult r = solver.solve_load(gap, load);
  const double solve_ms = ms_since(start);
  const double error =
      reference ? (r.pressure - *reference).abs().maxCoeff() / reference->maxCoeff() : 0.0;
  std::ostringstream row;
  row.precision(4);
  row << n << "," << body.label << "," << (v.linearity ? 1 : 0) << "," << to_string(v.precision)
      << "," << v.tolerance << "," << r.iterations << "," << r.operator_applications << ","
      << (r.converged ? 1 : 0) << "," << r.residual << "," << r.contact_area / (kLength * kLength)
      << "," << r.max_pressure << "," << error << "," << apply_ms << "," << solve_ms << ","
      << solve_ms / apply_ms << "," << bench::peak_rss_mb() << "\n";
  std::cout << row.str() << std::flush;
  out << row.str();
  return r;
}

PeriodicOperator make_operator(const Grid& g, const Body& body, const Field& kernel,
                               Precision precision) {
  return PeriodicOperator(g, kernel, exact_method(body.stack), Planning::estimate, precision);
}

double median_apply_ms(PeriodicOperator& op, const Field& p) {
  Field u;
  op.apply(p, u);  // warm-up
  std::vector<double> times;
  for (int k = 0; k < 5; ++k) {
    const auto start = Clock::now();
    op.apply(p, u);
    times.push_back(ms_since(start));
  }
  return detail::median(times);
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Contact solver cost on a periodic rough surface"};
  std::string path = "bench/results/rough_contact.csv";
  app.add("output", path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {1024, 2048, 4096};
  app.add("--sizes", sizes, "grid sizes N (N x N cells)").show_default();
  std::ptrdiff_t original_up_to = 4096;
  app.add("--original-up-to", original_up_to, "largest N on which the original iteration runs too")
      .show_default();
  std::ptrdiff_t single_up_to = 2048;
  app.add("--single-up-to", single_up_to, "largest N on which the single-precision solves run")
      .show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_rough_contact (periodic rough contact, load control)\n";
    bench::write_machine_header(out);
    out << "# surface = self-affine, H 0.8, rms slope " << kSlope << ", period " << kLength
        << " m, shortest wavelength " << kShortCutoffCells
        << " cells, roll-off period/4, seed 2004; gap = max z - z\n"
        << "# load = p_m/(E* g) = " << kLoad << " (E* of steel), tolerance 1e-10, preconditioned\n"
        << "# linearity = 1: one application per iteration (the solver's default); 0: Polonsky &\n"
        << "#   Keer's original (u = K p recomputed at every iteration, uniform start)\n"
        << "# apply_ms = one periodic application timed alone (median of 5); solve_over_apply =\n"
        << "#   solve_ms / apply_ms, the solve's cost in applications (elementwise work and the\n"
        << "#   preconditioner's FFT pair included); peak_rss_mb = the process's peak so far\n"
        << "N,body,linearity,precision,tolerance,iterations,applications,converged,residual,"
           "area_fraction,max_pressure_pa,pressure_error,apply_ms,solve_ms,solve_over_apply,"
           "peak_rss_mb\n";
    std::cout << out.str() << std::flush;
    for (const std::ptrdiff_t n : sizes) {
      const Grid g(n, n, kLength, kLength);
      const Field gap = bench::rough_gap(g);
      for (const Body& body : bodies()) {
        const auto frf = make_frf(body.stack);
        PeriodicKernelOptions o;
        o.threads = 2;
        const Field kernel = periodic_influence_kernel(g, *frf, o);
        PeriodicOperator exact = make_operator(g, body, kernel, Precision::double_precision);
        PeriodicOperator single = make_operator(g, body, kernel, Precision::single);
        const double exact_ms = median_apply_ms(exact, gap);
        const double single_ms = median_apply_ms(single, gap);
        const Field reference =
            solve_row(n, body, exact, gap, {true, Precision::double_precision, 1e-10}, exact_ms,
                      nullptr, out)
                .pressure;
        if (n <= original_up_to) {
          solve_row(n, body, exact, gap, {false, Precision::double_precision, 1e-10}, exact_ms,
                    &reference, out);
        }
        for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
          if (n > single_up_to) break;
          solve_row(n, body, single, gap, {true, Precision::single, tolerance}, single_ms,
                    &reference, out);
        }
      }
    }
    bench::write_text_file(path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_rough_contact: " << e.what() << "\n";
    return 1;
  }
}
