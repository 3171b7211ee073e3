// The hardness cap's cost against the elastic solve (docs/benchmarks.md, "Hardness"): the rough
// periodic surface of bench_rough_contact (bench/rough_gap.hpp) pressed by a rigid flat into
// steel and into TiN-coated steel (5 um), load control at p_m/(E* g) = 0.045 (about 10 % contact
// area on steel), tolerance 1e-10. Per grid and body: the elastic solve, then capped solves at a
// hardness of 2 and 1 times the elastic mean contact pressure (p_m A0 / A: the cap then binds on
// a tenth to two thirds of the contact), each with its iterations, operator applications
// (nested start's coarse ones apart) and wall time, their ratios to the elastic solve's, the
// plastic share of the contact and one application timed alone (the floor). Then, on the
// smallest grid, the capped solve's pressure error against a solve to 1e-13 at tolerances 1e-6,
// 1e-8, 1e-10 (speed against error). Prints `# key = value` headers and CSV rows, and writes the
// same to bench/results/hardness.csv (or OUTPUT).
//   bench_hardness [OUTPUT] [--sizes N ...]
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
#include "contact/plastic_report.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

const Material kSteel(210e9, 0.3);
constexpr double kLength = 1e-3;     // period [m]
constexpr double kLoad = 0.1 / 2.2;  // p_m / (E* g), E* of steel

struct Body {
  std::string label;
  LayerStack stack;
};

struct Timed {
  ContactResult result;
  double ms = 0;
};

Timed solve(SurfaceOperator& op, const Field& gap, double load, std::optional<double> hardness,
            double tolerance) {
  ContactOptions options;
  options.tolerance = tolerance;
  options.threads = 1;
  options.hardness = hardness;
  ContactSolver solver(op, options);
  const auto start = Clock::now();
  Timed t{solver.solve_load(gap, load), 0};
  t.ms = 1e3 * detail::seconds_since(start);
  return t;
}

void row(std::ostream& out, std::ptrdiff_t n, const Body& body, const std::string& cap_label,
         const Timed& t, const Timed& elastic, std::optional<double> hardness, const Grid& g,
         double apply_ms) {
  const double fraction =
      hardness ? plastic_report(t.result, *hardness, g).plastic_area_fraction : 0.0;
  std::ostringstream line;
  line.precision(4);
  line << n << "," << body.label << "," << cap_label << "," << (hardness ? *hardness : 0.0) << ","
       << t.result.iterations << "," << t.result.operator_applications << ","
       << t.result.coarse_applications << "," << t.ms << ","
       << static_cast<double>(t.result.operator_applications) / elastic.result.operator_applications
       << "," << t.ms / elastic.ms << "," << t.ms / apply_ms << ","
       << t.result.contact_area / (g.lx() * g.ly()) << "," << fraction << ","
       << (t.result.converged ? 1 : 0) << "\n";
  std::cout << line.str() << std::flush;
  out << line.str();
}

// The capped solve's error against a tight one, at the tolerances a user would choose.
void error_rows(std::ostream& out, std::ptrdiff_t n, const Body& body, SurfaceOperator& op,
                const Field& gap, double load, double hardness) {
  const Timed reference = solve(op, gap, load, hardness, 1e-13);
  for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
    const Timed t = solve(op, gap, load, hardness, tolerance);
    std::ostringstream line;
    line.precision(4);
    line << "# error," << n << "," << body.label << "," << tolerance << "," << t.result.iterations
         << "," << t.result.operator_applications << "," << t.ms << ","
         << (t.result.pressure - reference.result.pressure).abs().maxCoeff() / hardness << ","
         << (t.result.converged ? 1 : 0) << "\n";
    std::cout << line.str() << std::flush;
    out << line.str();
  }
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"The hardness cap against the elastic solve"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/hardness.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512, 1024, 2048};
  app.add("--sizes", sizes, "Grid sizes N (even)")
      .comma_separated()
      .show_default()
      .range(std::ptrdiff_t{64}, std::ptrdiff_t{1} << 14);
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_hardness (the hardness cap against the elastic solve)\n";
    bench::write_machine_header(out);
    out << "# surface = bench/rough_gap.hpp (self-affine, H 0.8, rms slope "
        << bench::rough_rms_slope << ", shortest wavelength " << bench::rough_short_cutoff_cells
        << " cells), period " << kLength << " m, periodic; load p_m/(E* g) = " << kLoad
        << " (E* of steel); tolerance 1e-10; one thread\n"
        << "# cap = elastic, or the hardness as a multiple of the elastic mean contact pressure\n"
        << "# applications = fine-grid applications (coarse = the nested start's); "
           "applications_ratio, time_ratio: against the elastic row; solve_over_apply: the\n"
        << "#   solve's time in applications timed alone; plastic_fraction: of the contact area\n"
        << "# '# error' rows: N, body, tolerance, iterations, applications, solve_ms, max |p - "
           "p_ref| / H against a solve to 1e-13, converged (hardness 1 x)\n"
        << "N,body,cap,hardness_pa,iterations,applications,coarse_applications,solve_ms,"
           "applications_ratio,time_ratio,solve_over_apply,area_fraction,plastic_fraction,"
           "converged\n";
    std::cout << out.str() << std::flush;
    const std::vector<Body> bodies = {
        {"steel", LayerStack(kSteel)},
        {"TiN 5 um on steel",
         LayerStack({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSteel)}};
    for (const std::ptrdiff_t n : sizes) {
      const Grid g(n, n, kLength, kLength);
      const Field gap = bench::rough_gap(g);
      const double load =
          kLoad * kSteel.plane_strain_modulus() * bench::rough_rms_slope * kLength * kLength;
      for (const Body& body : bodies) {
        OperatorOptions o;
        o.boundary = Boundary::periodic;
        o.threads = 1;
        const BuiltOperator built = make_operator(g, body.stack, o);
        Field uz;
        const Timed elastic = solve(*built.op, gap, load, std::nullopt, 1e-10);
        const double apply_ms =
            1e3 * detail::time_applications(*built.op, elastic.result.pressure, uz, 5);
        row(out, n, body, "elastic", elastic, elastic, std::nullopt, g, apply_ms);
        const double mean_contact = load / elastic.result.contact_area;
        for (const double factor : {2.0, 1.0}) {
          const double hardness = factor * mean_contact;
          const Timed capped = solve(*built.op, gap, load, hardness, 1e-10);
          row(out, n, body, std::to_string(static_cast<int>(factor)) + "x", capped, elastic,
              hardness, g, apply_ms);
        }
        if (n == sizes.front()) error_rows(out, n, body, *built.op, gap, load, mean_contact);
      }
    }
    bench::write_text_file(out_path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_hardness: " << e.what() << "\n";
    return 1;
  }
}
