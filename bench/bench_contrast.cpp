// Contact solver on a stiff thin coating: iterations against the stiffness contrast and the
// contact fraction, for the two preconditioner symbols (contact/detail/fourier_preconditioner.hpp).
// A rigid flat on the periodic rough surface of the rough-contact benchmarks (bench/rough_gap.hpp)
// presses a coating 2 um thick, of Young's modulus `contrast` times steel's (nu 0.3), bonded on
// steel; period 0.5 mm, so the coating is half a cell thick at 128^2 and the operator's k K^
// spans nearly the whole ratio of the moduli over the grid's wavenumbers. For each contrast the
// load of each target contact fraction is found by bisection (with the operator-adapted symbol),
// then both symbols solve that load from the same start: their iterations, applications, status
// and the largest difference of their pressures where both converged.
// Prints `# key = value` headers and CSV rows, and writes the same to bench/results/contrast.csv
// (or OUTPUT).
//   bench_contrast [OUTPUT] [--n N] [--contrasts C ...] [--fractions F ...] [--surface S]
//                  [--max-iterations M]
#include <cmath>
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
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace {

using namespace coatfft;

const Material kSteel(210e9, 0.3);
constexpr double kPeriod = 0.5e-3;    // [m]
constexpr double kThickness = 2e-6;   // [m]
constexpr double kTolerance = 1e-10;  // the solver's default

double contact_fraction(const ContactResult& r) {
  return r.contact_area / (kPeriod * kPeriod);
}

ContactResult solve(PeriodicOperator& op, const Field& gap, double load,
                    PreconditionerSymbol symbol, int max_iterations) {
  ContactOptions options;
  options.preconditioner_symbol = symbol;
  options.max_iterations = max_iterations;
  return ContactSolver(op, options).solve_load(gap, load);
}

// The load whose contact fraction is `fraction`: bisection on log(load), 12 halvings of a
// bracket of 2^20 (a load within 3 % of the target's).
double load_for_fraction(PeriodicOperator& op, const Field& gap, double fraction, int max_it) {
  const double nominal = kSteel.plane_strain_modulus() * bench::rough_rms_slope * kPeriod * kPeriod;
  double lo = std::log(1e-4 * nominal);
  double hi = std::log(1e2 * nominal);
  for (int k = 0; k < 12; ++k) {
    const double mid = 0.5 * (lo + hi);
    const ContactResult r =
        solve(op, gap, std::exp(mid), PreconditionerSymbol::operator_adapted, max_it);
    (contact_fraction(r) < fraction ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

// A rougher surface, down to the grid's scale: self-affine (H 0.8, rms height 0.2 um) with the
// default cut-offs (shortest wavelength 2 cells); flat to the contact set's last cells.
Field grid_scale_gap(const Grid& grid) {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_height = 0.2e-6;
  spec.seed = 5;
  const Field z = self_affine_surface(grid, spec);
  return z.maxCoeff() - z;
}

void row(std::ostream& out, double contrast, double target, double load, const char* symbol,
         const ContactResult& r, double difference) {
  std::ostringstream line;
  line.precision(4);
  line << contrast << "," << target << "," << load << "," << symbol << "," << contact_fraction(r)
       << "," << r.iterations << "," << r.operator_applications << "," << to_string(r.status) << ","
       << r.residual << "," << difference << "\n";
  std::cout << line.str() << std::flush;
  out << line.str();
}

// The `# key = value` header and the CSV's column names.
void write_header(std::ostream& out, const std::string& surface, long n, int max_iterations) {
  out << "# benchmark = bench_contrast (stiff thin coating, periodic rough contact)\n";
  bench::write_machine_header(out);
  out << "# surface = " << surface << "\n";
  out << "# N = " << n << ", period " << kPeriod << " m, coating " << kThickness
      << " m of E = contrast x 210 GPa (nu 0.3) bonded on steel\n"
      << "# load: bisection to the target contact fraction; tolerance " << kTolerance
      << ", max_iterations " << max_iterations << "\n"
      << "# symbol: half_space = |k| (the default), operator_adapted = sqrt(|k| / K^)\n"
      << "# pressure_difference = max |p_half_space - p_operator_adapted| / max p, where both "
         "converged (-1 otherwise)\n"
      << "contrast,target_fraction,load_n,symbol,contact_fraction,iterations,applications,"
         "status,residual,pressure_difference\n";
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Contact iterations against stiffness contrast and contact"};
  std::string path = "bench/results/contrast.csv";
  app.add("output", path, "CSV file").show_default();
  long n = 128;
  app.add("--n", n, "grid size N (N x N cells)").positive().show_default();
  std::vector<double> contrasts = {1, 10, 100, 1000};
  app.add("--contrasts", contrasts, "E_coating / E_substrate").positive().show_default();
  std::vector<double> fractions = {0.1, 0.3, 0.5, 0.7, 0.9};
  app.add("--fractions", fractions, "target contact fractions").range(0.01, 0.99).show_default();
  std::string surface = "smooth";
  app.add("--surface", surface, "smooth (bench/rough_gap.hpp) or grid-scale").show_default();
  int max_iterations = 20000;
  app.add("--max-iterations", max_iterations, "iteration limit of every solve").positive();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    write_header(out, surface, n, max_iterations);
    std::cout << out.str() << std::flush;
    const Grid grid(n, n, kPeriod, kPeriod);
    const Field gap = surface == "smooth" ? bench::rough_gap(grid) : grid_scale_gap(grid);
    for (const double contrast : contrasts) {
      const Material coating(contrast * 210e9, 0.3);
      const LayerStack stack({{coating, kThickness, Interface::bonded}}, kSteel);
      PeriodicKernelOptions kernel_options;
      kernel_options.threads = 2;
      const Field kernel = periodic_influence_kernel(grid, *make_frf(stack), kernel_options);
      PeriodicOperator op(grid, kernel, exact_method(stack));
      for (const double target : fractions) {
        const double load = load_for_fraction(op, gap, target, max_iterations);
        const ContactResult old =
            solve(op, gap, load, PreconditionerSymbol::half_space, max_iterations);
        const ContactResult now =
            solve(op, gap, load, PreconditionerSymbol::operator_adapted, max_iterations);
        const double difference =
            old.converged && now.converged
                ? (old.pressure - now.pressure).abs().maxCoeff() / now.pressure.maxCoeff()
                : -1.0;
        row(out, contrast, target, load, "half_space", old, difference);
        row(out, contrast, target, load, "operator_adapted", now, difference);
      }
    }
    bench::write_text_file(path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_contrast: " << e.what() << "\n";
    return 1;
  }
}
