// How converged the references of the speed-against-error sweep are (bench/sweep_cases.hpp): the
// Hankel reference used (split route, rel_tol 1e-10) against a tighter one (1e-13) and against
// the independent direct route (no closed-form part), the interpolated table of RadialReference
// against fresh evaluations between its nodes, and for the homogeneous case the Hankel value
// against the closed form; 97 radii in [0, r_max]. Prints a CSV (and writes it with --output),
// which scripts/plot_pareto.py renders into docs/benchmarks.md.
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "bench/sweep_cases.hpp"
#include "core/detail/timing.hpp"
#include "validation/hertz.hpp"

int main(int argc, char** argv) {
  namespace sweep = coatfft::sweep;
  using coatfft::detail::seconds_since;
  using sweep::fmt;
  coatfft::bench::CommandLine app{"Convergence of the references of bench_sweep"};
  std::string output;
  app.add("--output", output, "Also write the CSV here");
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream os;
    os << "# bench_reference_check: max differences / u_ref(0) over 97 radii in [0, "
          "1.5 sqrt(2) a], node-straddling\n"
       << "case,u_ref0_m,table_nodes,table_dr_over_a,table_s,eval_ms,diff_tol_1e-13,"
          "diff_direct_route,diff_table_interpolation,diff_closed_form\n";
    for (const sweep::SweepCase& c : sweep::all_cases()) {
      const auto t_table = std::chrono::steady_clock::now();
      const sweep::RadialReference u_ref(c, sweep::max_radius(c));
      const double table_s = seconds_since(t_table);
      const double u0 = u_ref(0.0);
      double d_tight = 0.0, d_direct = 0.0, d_table = 0.0, d_closed = 0.0, eval_s = 0.0;
      const int count = 97;
      for (int q = 0; q < count; ++q) {
        // Irrational steps put the radii between the table's nodes.
        const double r = sweep::max_radius(c) * (q + 0.5 * M_SQRT1_2) / count;
        const auto t0 = std::chrono::steady_clock::now();
        const double u = u_ref.exact(r);
        eval_s += seconds_since(t0);
        d_tight = std::max(d_tight, std::abs(u - u_ref.exact(r, 1e-13)) / u0);
        d_direct = std::max(d_direct, std::abs(u - u_ref.exact(r, sweep::reference_tolerance,
                                                               coatfft::HankelRoute::direct)) /
                                          u0);
        d_table = std::max(d_table, std::abs(u - u_ref(r)) / u0);
        if (c.stack.is_homogeneous())
          d_closed =
              std::max(d_closed,
                       std::abs(u - coatfft::hertz_displacement(
                                        r, c.p0, c.a, c.stack.substrate().plane_strain_modulus())) /
                           u0);
      }
      os << c.name << ',' << fmt(u0) << ',' << u_ref.nb_nodes() << ','
         << fmt(u_ref.node_spacing() / c.a) << ',' << fmt(table_s) << ','
         << fmt(1e3 * eval_s / count) << ',' << fmt(d_tight) << ',' << fmt(d_direct) << ','
         << fmt(d_table) << ',' << (c.stack.is_homogeneous() ? fmt(d_closed) : "n/a") << '\n';
    }
    std::cout << os.str();
    if (!output.empty()) coatfft::bench::write_text_file(output, os.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_reference_check: " << e.what() << "\n";
    return 1;
  }
}
