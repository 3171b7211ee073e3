// Partial slip against the normal solve on the same grid (docs/benchmarks.md, "Partial slip"): a
// rigid sphere on bare steel and on TiN 5 um on steel, free and periodic surfaces (the domain 8
// contact radii wide, a/dx = N/8), the tangential load 0.6 mu P from rest (mu = 0.3). Per case:
// the normal solve's iterations, applications and time; the partial slip step's (the normal solves
// of its coupling and the tangential iterations, their 3 x 3 applications of the surface
// response counted apart) and time; one application of each operator, the floor the solves are
// made of. Then the error against Cattaneo-Mindlin against the grid (nu = 0.4999, a/dx = 8 to
// 64). Prints `# key = value` headers and CSV rows, and writes the same to
// bench/results/partial_slip.csv (or OUTPUT).
//   bench_partial_slip [OUTPUT] [--sizes N ...]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "contact/indenter.hpp"
#include "contact/partial_slip.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "validation/cattaneo_mindlin.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

constexpr double kBall = 0.01, kLoad = 10.0, kMu = 0.3, kShare = 0.6;
const Material kSteel(210e9, 0.3);

struct Case {
  std::string label;
  LayerStack body;
  Boundary boundary;
};

// Median wall time [ms] of `repeat` 3 x 3 applications of `response` to (p, q_x, 0).
double response_ms(RelativeSurfaceResponse& response, const Field& p, int repeat) {
  std::vector<double> ms;
  std::array<Field, 3> u;
  for (int k = 0; k < repeat; ++k) {
    const auto start = Clock::now();
    response.apply(p, &p, nullptr, u);
    ms.push_back(1e3 * detail::seconds_since(start));
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

// One row: the normal solve, then the partial slip step from rest, on one grid.
std::string measure(std::ptrdiff_t n, const Case& c) {
  const double a =
      hertz_sphere_for_load(kLoad, kBall, kSteel.plane_strain_modulus()).contact_radius;
  const Grid g(n, n, 8 * a, 8 * a);
  OperatorOptions o;
  o.method = exact_method(c.body);
  o.boundary = c.boundary;
  const BuiltOperator built = make_operator(g, c.body, o);
  TangentialOptions t;
  t.boundary = c.boundary;
  auto start = Clock::now();
  RelativeSurfaceResponse response(make_tangential_operator(g, c.body, t).op);
  const double response_setup_ms = 1e3 * detail::seconds_since(start);
  const Field h = height(g, Sphere{kBall});
  ContactSolver solver(*built.op);
  start = Clock::now();
  const ContactResult normal = solver.solve_load(h, kLoad);
  const double normal_ms = 1e3 * detail::seconds_since(start);
  PartialSlipOptions options;
  options.friction = kMu;
  start = Clock::now();
  const PartialSlipState rest = rest_state(response, solver.solve_load(h, kLoad));
  const PartialSlipResult r =
      solve_partial_slip(solver, response, h, ContactControl::load, kLoad, TangentialControl::load,
                         kShare * kMu * kLoad, options, rest);
  const double slip_ms = 1e3 * detail::seconds_since(start);
  Field uz;
  const double apply_ms = 1e3 * detail::time_applications(*built.op, normal.pressure, uz, 5);
  const double response_apply_ms = response_ms(response, normal.pressure, 5);
  const int tangential_applications = r.operator_applications;  // all, normal included
  std::ostringstream row;
  row.precision(4);
  row << n << "," << c.label << "," << (c.boundary == Boundary::periodic ? "periodic" : "free")
      << "," << a / g.dx() << "," << normal.iterations << "," << normal.operator_applications << ","
      << normal_ms << "," << r.coupling_solves << "," << r.iterations << ","
      << tangential_applications << "," << slip_ms << "," << slip_ms / normal_ms << "," << apply_ms
      << "," << response_apply_ms << "," << response_setup_ms << ","
      << std::sqrt(r.stick_area / std::numbers::pi) / a << "," << (r.converged ? 1 : 0) << "\n";
  return row.str();
}

// The error against Cattaneo-Mindlin on grids 4a + 1 cells wide, a/dx = `cells`.
std::string reference_row(int cells) {
  const Material m(2e9, Material::max_poisson_ratio);
  const CattaneoMindlin cm = cattaneo_mindlin(20.0, kBall, m, kMu);
  const double a = cm.hertz.contact_radius, l = (4 * cells + 1) * a / cells;
  const Grid g(4 * cells + 1, 4 * cells + 1, l, l);
  const BuiltOperator built = make_operator(g, LayerStack(m));
  RelativeSurfaceResponse response(make_tangential_operator(g, LayerStack(m)).op);
  const Field h = height(g, Sphere{kBall});
  ContactSolver solver(*built.op);
  PartialSlipOptions options;
  options.friction = kMu;
  const double q = kShare * kMu * 20.0;
  const auto start = Clock::now();
  const PartialSlipResult r =
      solve_partial_slip(solver, response, h, ContactControl::load, 20.0, TangentialControl::load,
                         q, options, rest_state(response, solver.solve_load(h, 20.0)));
  const double ms = 1e3 * detail::seconds_since(start);
  std::ostringstream row;
  row.precision(5);
  row << "# reference," << cells << "," << g.nx() << ","
      << std::sqrt(r.stick_area / std::numbers::pi) / cm.stick_radius(q) << ","
      << r.tangential_shift / cm.shift(q) << "," << rms_traction_error(g, r.qx, cm, q) << ","
      << r.iterations << "," << r.operator_applications << "," << ms << "\n";
  return row.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Partial slip against the normal solve"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/partial_slip.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512};
  app.add("--sizes", sizes, "Grid sizes N (even)")
      .comma_separated()
      .show_default()
      .range(std::ptrdiff_t{16}, std::ptrdiff_t{1} << 14);
  std::vector<int> reference_cells = {8, 16, 32, 64};
  app.add("--reference-cells", reference_cells, "a/dx of the Cattaneo-Mindlin rows")
      .comma_separated()
      .show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream csv;
    csv << "# bench = bench_partial_slip (partial slip against the normal solve)\n";
    coatfft::bench::write_machine_header(csv);
    csv << "# sphere R = " << kBall << " m, load " << kLoad << " N, mu = " << kMu
        << ", Q = " << kShare << " mu P from rest; domain 8 a wide; tolerance: the normal 1e-10, "
        << "the tangential 1e-8; one thread, estimate plans\n"
        << "# slip_applications: all of the step (its normal solves' and the 3 x 3 response's); "
           "apply_ms: one normal application, response_apply_ms: one 3 x 3 application\n"
        << "# reference rows: a/dx, N, stick radius / Cattaneo's, shift / Cattaneo-Mindlin's, rms "
           "traction error / (mu p0), tangential iterations, applications, ms (nu = 0.4999, "
           "20 N, E = 2 GPa)\n"
        << "n,body,boundary,a_over_dx,normal_iterations,normal_applications,normal_ms,"
           "coupling_solves,slip_iterations,slip_applications,slip_ms,slip_over_normal,apply_ms,"
           "response_apply_ms,response_setup_ms,stick_radius_over_a,converged\n";
    std::cout << csv.str() << std::flush;
    const LayerStack coated({{Material(400e9, 0.25), 5e-6, Interface::bonded}}, kSteel);
    const std::vector<Case> cases = {{"steel", LayerStack(kSteel), Boundary::free},
                                     {"steel", LayerStack(kSteel), Boundary::periodic},
                                     {"TiN 5 um on steel", coated, Boundary::free},
                                     {"TiN 5 um on steel", coated, Boundary::periodic}};
    for (const std::ptrdiff_t n : sizes)
      for (const Case& c : cases) {
        const std::string row = measure(n, c);
        std::cout << row << std::flush;
        csv << row;
      }
    for (const int cells : reference_cells) {
      const std::string row = reference_row(cells);
      std::cout << row << std::flush;
      csv << row;
    }
    coatfft::bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_partial_slip: " << e.what() << '\n';
    return 1;
  }
}
