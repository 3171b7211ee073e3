// Load sweeps on a periodic rough surface: the same loads solved one by one from the usual
// start (nested on a rough surface), and as one sweep (ContactSolver::solve_sweep), each solve
// started from the solutions before it (the secant through the last two). A self-affine surface (H
// = 0.8, rms slope 0.05, shortest wavelength 16 cells, roll-off at a quarter of the period) pressed
// by a rigid flat into steel and into TiN-coated steel (5 um), periodic boundaries, tolerance
// 1e-10, one thread; the loads spaced geometrically from about 1 % to about 30 % contact area (A/A0
// ~ kappa p_m/(E* g), kappa about 2.2). Per load: iterations, operator applications and wall time
// of both, and the largest pressure difference between them (both converge to the same discrete
// solution). Prints `# key = value` headers and CSV rows, and writes the same to
// bench/results/load_sweep.csv (or OUTPUT).
//   bench_load_sweep [OUTPUT] [--sizes N ...] [--loads K]
#include <chrono>
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
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

const Material kSweepSteel(210e9, 0.3);
constexpr double kSweepSlope = bench::rough_rms_slope;
constexpr double kSweepLength = 1e-3;  // period [m]

struct SweepBody {
  std::string label;
  LayerStack stack;
};

// `count` loads [N] spaced geometrically between mean pressures that give about 1 % and 30 %
// contact area on steel.
std::vector<double> sweep_loads(int count) {
  const double unit = kSweepSteel.plane_strain_modulus() * kSweepSlope * kSweepLength *
                      kSweepLength / 2.2;  // p_m A0 at A/A0 = 1
  std::vector<double> loads;
  for (int k = 0; k < count; ++k)
    loads.push_back(unit * 0.01 * std::pow(30.0, count > 1 ? double(k) / (count - 1) : 0.0));
  return loads;
}

// A solve's applications in fine ones: its coarse grids' (a nested start's) at a quarter of the
// cells or fewer counted as a quarter, an upper bound of their cost.
double cost(const ContactResult& r) {
  return r.operator_applications + 0.25 * r.coarse_applications;
}

// The rows of one body on one grid: the cold solves, then the sweep, side by side.
std::string measure(std::ptrdiff_t n, const SweepBody& body, const std::vector<double>& loads) {
  const Grid g(n, n, kSweepLength, kSweepLength);
  OperatorOptions o;
  o.method = exact_method(body.stack);
  o.boundary = Boundary::periodic;
  const BuiltOperator built = make_operator(g, body.stack, o);
  const Field gap = bench::rough_gap(g);
  ContactSolver solver(*built.op);
  std::vector<ContactResult> cold;
  std::vector<double> cold_ms;
  for (const double load : loads) {
    const auto start = Clock::now();
    cold.push_back(solver.solve_load(gap, load));
    cold_ms.push_back(1e3 * detail::seconds_since(start));
  }
  const auto start = Clock::now();
  const std::vector<ContactResult> warm = solver.solve_sweep(gap, ContactControl::load, loads);
  const double sweep_ms = 1e3 * detail::seconds_since(start);
  std::ostringstream rows;
  rows.precision(4);
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const double difference =
        (warm[k].pressure - cold[k].pressure).abs().maxCoeff() / cold[k].max_pressure;
    rows << n << "," << body.label << "," << loads[k] << ","
         << cold[k].contact_area / (kSweepLength * kSweepLength) << "," << cold[k].iterations << ","
         << cold[k].operator_applications << "," << cold_ms[k] << "," << warm[k].iterations << ","
         << warm[k].operator_applications << "," << (cold[k].converged ? 1 : 0)
         << (warm[k].converged ? 1 : 0) << "," << difference << "," << cold[k].coarse_applications
         << "," << warm[k].coarse_applications << "," << cost(cold[k]) << "," << cost(warm[k])
         << "\n";
  }
  int cold_total = 0, warm_total = 0;
  double cold_total_ms = 0, cold_cost = 0, warm_cost = 0;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    cold_total += cold[k].operator_applications;
    warm_total += warm[k].operator_applications;
    cold_cost += cost(cold[k]);
    warm_cost += cost(warm[k]);
    cold_total_ms += cold_ms[k];
  }
  rows << "# total " << n << " " << body.label << ": applications cold " << cold_total << ", sweep "
       << warm_total << " (" << double(warm_total) / cold_total << "); cost cold " << cold_cost
       << ", sweep " << warm_cost << " (" << warm_cost / cold_cost << "); time cold "
       << cold_total_ms << " ms, sweep " << sweep_ms << " ms (" << sweep_ms / cold_total_ms
       << ")\n";
  return rows.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Load sweeps: warm-started solves against cold ones"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/load_sweep.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512};
  app.add("--sizes", sizes, "Grid sizes N (even)")
      .comma_separated()
      .show_default()
      .range(std::ptrdiff_t{16}, std::ptrdiff_t{1} << 14);
  int count = 16;
  app.add("--loads", count, "Loads per sweep").show_default().positive();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream csv;
    csv << "# bench = bench_load_sweep (warm-started sweeps against cold solves)\n";
    coatfft::bench::write_machine_header(csv);
    csv << "# surface = self-affine H 0.8, rms slope " << kSweepSlope
        << ", shortest wavelength 16 cells, roll-off L/4, L = " << kSweepLength
        << " m, periodic; rigid flat; tolerance 1e-10, one thread, estimate plans\n"
        << "# cold = each load solved alone (the usual start: nested on a rough surface); "
           "sweep = solve_sweep, each load from the secant through the solutions before it\n"
        << "# p_difference = max |p_sweep - p_cold| / max p_cold; *_coarse_applications: on "
           "the nested start's coarser grids; *_cost = applications + coarse / 4 (fine "
           "applications' worth)\n"
        << "n,body,load,area_fraction,cold_iterations,cold_applications,cold_ms,"
           "sweep_iterations,sweep_applications,converged,p_difference,"
           "cold_coarse_applications,sweep_coarse_applications,cold_cost,sweep_cost\n";
    std::cout << csv.str() << std::flush;
    const std::vector<SweepBody> bodies = {
        {"steel", LayerStack(kSweepSteel)},
        {"TiN 5 um on steel",
         LayerStack({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSweepSteel)}};
    for (const std::ptrdiff_t n : sizes)
      for (const SweepBody& body : bodies) {
        const std::string rows = measure(n, body, sweep_loads(count));
        std::cout << rows << std::flush;
        csv << rows;
      }
    coatfft::bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_load_sweep: " << e.what() << '\n';
    return 1;
  }
}
