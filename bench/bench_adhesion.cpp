// The adhesive contact's cost against the non-adhesive solve and its error against
// Maugis-Dugdale (docs/benchmarks.md, "Adhesion"): a rigid sphere (R = 1 mm) on a soft half-space
// (E* = 1 GPa, w = 0.05 J/m^2) at Maugis' lambda = 1, an approach path from D = 2 down in steps
// of 0.1 of Maugis' approach scale until the contact jumps off (tests/adhesive_sphere.hpp's
// path), on grids 6 a_s wide. Per grid: the path's rounds, iterations, operator applications and
// time per step, those of a non-adhesive solve at the first approach (the floor a step is
// measured against), and the pull-off's error. Prints `# key = value` headers and CSV rows, and
// writes the same to bench/results/adhesion.csv (or OUTPUT).
//   bench_adhesion [OUTPUT] [--sizes N ...]
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "contact/adhesive_contact.hpp"
#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "validation/maugis_dugdale.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

constexpr double kRadius = 1e-3, kModulus = 1e9, kWork = 0.05, kLambda = 1.0;

std::string measure(std::ptrdiff_t n) {
  constexpr double pi = std::numbers::pi;
  const double k = 4 * kModulus / 3;
  const double sigma0 = 0.5 * kLambda * std::cbrt(pi * kWork * k * k / kRadius);
  const AdhesionOptions law{kWork, kWork / sigma0};
  const double a_s = std::cbrt(pi * kWork * kRadius * kRadius / k);
  const double d_s = std::cbrt(pi * pi * kWork * kWork * kRadius / (k * k));
  const Grid g(n, n, 6 * a_s, 6 * a_s);
  const BuiltOperator built = make_operator(g, LayerStack(Material(kModulus * 0.91, 0.3)), {});
  ContactSolver solver(*built.op);
  const Field h = height(g, Sphere{kRadius});
  std::vector<double> approaches;
  for (int s = 20; s >= -20; --s) approaches.push_back(0.1 * s * d_s);
  auto start = Clock::now();
  const ContactResult plain = solver.solve_approach(h, approaches.front());
  const double plain_ms = 1e3 * detail::seconds_since(start);
  start = Clock::now();
  const std::vector<AdhesiveResult> path =
      solve_adhesive_path(solver, h, ContactControl::approach, approaches, law);
  const double path_ms = 1e3 * detail::seconds_since(start);
  int rounds = 0, iterations = 0, applications = 0, steps = 0;
  double pull_off = 0;
  bool converged = true;
  for (const AdhesiveResult& r : path) {
    rounds += r.rounds;
    iterations += r.contact.iterations;
    applications += r.contact.operator_applications;
    pull_off = std::min(pull_off, r.contact.load);
    converged = converged && r.converged;
    ++steps;
  }
  const double reference = MaugisDugdale(kRadius, kModulus, kWork, law.range).pull_off_load();
  std::ostringstream row;
  row.precision(4);
  row << n << "," << a_s / g.dx() << "," << steps << "," << static_cast<double>(rounds) / steps
      << "," << static_cast<double>(applications) / steps << "," << path_ms / steps << ","
      << plain.operator_applications << "," << plain_ms << ","
      << static_cast<double>(applications) / steps / plain.operator_applications << ","
      << pull_off / (pi * kWork * kRadius) << "," << reference / (pi * kWork * kRadius) << ","
      << std::abs(pull_off / reference - 1) << "," << (converged ? 1 : 0) << "\n";
  return row.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"The adhesive contact against the non-adhesive solve"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/adhesion.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {64, 128, 256};
  app.add("--sizes", sizes, "Grid sizes N").comma_separated().show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_adhesion (adhesive contact against the non-adhesive solve)\n";
    coatfft::bench::write_machine_header(out);
    out << "# sphere R = 1 mm on E* = 1 GPa, w = 0.05 J/m^2, lambda = 1, approach path D = 2 .. "
           "-2 in steps of 0.1; domain 6 a_s; tolerance 1e-10; one thread\n"
        << "# per step: rounds of the outer iteration, operator applications (K chi_I and the "
           "contact solves), time; plain = one non-adhesive solve at D = 2 (cold)\n"
        << "N,a_s_over_dx,steps,rounds_per_step,applications_per_step,ms_per_step,"
           "plain_applications,plain_ms,step_over_plain,pull_off,maugis_dugdale,"
           "pull_off_error,converged\n";
    std::cout << out.str() << std::flush;
    for (const std::ptrdiff_t n : sizes) {
      const std::string row = measure(n);
      std::cout << row << std::flush;
      out << row;
    }
    coatfft::bench::write_text_file(out_path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_adhesion: " << e.what() << "\n";
    return 1;
  }
}
