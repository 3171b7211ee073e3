// Cost of the stresses on a plane against one surface-displacement application, side by side in
// one run: DC-FFT (Love's coefficients, the pruned padded transforms of DcfftOperator) and
// StressOperator with 1 and 8 planes under a pressure, and 1 plane under a pressure and two
// tractions, on N x N grids of a TiN-coated steel body; and the whole surface response of that
// body, (u_x, u_y, u_z) under (p, q_x, q_y) by CerrutiOperator
// (convolution/kernels/traction_kernels.hpp). Also each operator's setup time and memory_bytes, and
// this process's peak RSS after the largest 8-plane operator. Prints "# key = value" headers and
// CSV rows, and writes them to bench/results/stress.csv.
//   bench_stress [OUTPUT] [--max-n N]
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "stress/stress_operator.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using namespace coatfft;

// Median milliseconds of `f` over about `budget_s` seconds (3 to 41 runs) after one warm-up.
double median_ms(const std::function<void()>& f, double budget_s = 1.0) {
  f();
  const auto t0 = Clock::now();
  f();
  const double once = detail::seconds_since(t0);
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 3, 41);
  std::vector<double> ms;
  for (int r = 0; r < reps; ++r) {
    const auto s = Clock::now();
    f();
    ms.push_back(1e3 * detail::seconds_since(s));
  }
  return detail::median(ms);
}

Field random_load(std::ptrdiff_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(0.0, 1e9);
  return Field::NullaryExpr(n, n, [&] { return dist(rng); });
}

struct Row {
  std::ptrdiff_t n;
  std::string what;
  int planes;
  double setup_s, apply_ms, per_plane_over_surface;
  double memory_mib;
};

// The stress operator's rows (1 and 8 planes under p, 1 plane under p, q_x, q_y) on a free or a
// periodic surface; the ratio over the free surface's application `surface_ms`.
void add_stress_rows(const Grid& grid, const LayerStack& body, const Field& p, const Field& qx,
                     const Field& qy, double surface_ms, bool periodic, std::vector<Row>& rows) {
  const std::vector<double> eight{1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 6e-4, 7e-4, 8e-4};
  const std::string prefix = periodic ? "periodic " : "";
  for (auto [what, planes, tangential] :
       {std::tuple{"stress p", 1, false}, {"stress p", 8, false}, {"stress p qx qy", 1, true}}) {
    StressOperatorOptions o;
    o.tangential = tangential;
    o.boundary = periodic ? Boundary::periodic : Boundary::free;
    o.planning = Planning::measure;
    const std::vector<double> depths(eight.begin(), eight.begin() + planes);
    const auto t0 = Clock::now();
    const auto op = make_stress_operator(grid, body, depths, o);
    const double setup = detail::seconds_since(t0);
    std::vector<PlaneStress> s;
    const double ms =
        median_ms([&] { op->apply(p, tangential ? &qx : nullptr, tangential ? &qy : nullptr, s); });
    rows.push_back({grid.nx(), prefix + what, planes, setup, ms, ms / planes / surface_ms,
                    static_cast<double>(op->memory_bytes()) / (1 << 20)});
  }
}

// The 3 x 3 surface response (CerrutiOperator) on a free or periodic surface.
Row response_row(const Grid& grid, const LayerStack& body, const Field& p, const Field& qx,
                 const Field& qy, double surface_ms, bool periodic) {
  TangentialOptions options;
  options.planning = Planning::measure;
  options.boundary = periodic ? Boundary::periodic : Boundary::free;
  const auto t0 = Clock::now();
  const std::unique_ptr<CerrutiOperator> response =
      make_tangential_operator(grid, body, options).op;
  const double setup = detail::seconds_since(t0);
  std::array<Field, 3> u;
  const double ms = median_ms([&] { response->apply(p, &qx, &qy, u); });
  return {grid.nx(),
          std::string(periodic ? "periodic " : "") + "surface 3x3 p qx qy",
          0,
          setup,
          ms,
          ms / surface_ms,
          static_cast<double>(response->memory_bytes()) / (1 << 20)};
}

std::vector<Row> measure(std::ptrdiff_t n) {
  const Grid grid(n, n, 4e-3, 4e-3);
  const LayerStack body({{Material(400e9, 0.25), 1e-4, Interface::bonded}}, Material(210e9, 0.3));
  OperatorOptions surface_options;
  surface_options.method = Method::dcfft;
  surface_options.planning = Planning::measure;
  auto t0 = Clock::now();
  BuiltOperator surface = make_operator(love_kernel(grid, 2.3e11), surface_options);
  const double surface_setup = detail::seconds_since(t0);
  const Field p = random_load(n, 1), qx = random_load(n, 2), qy = random_load(n, 3);
  Field u;
  const double surface_ms = median_ms([&] { surface.op->apply(p, u); });
  std::vector<Row> rows{{n, "surface dcfft", 0, surface_setup, surface_ms, 1.0, 0.0}};
  rows.push_back(response_row(grid, body, p, qx, qy, surface_ms, false));
  add_stress_rows(grid, body, p, qx, qy, surface_ms, false, rows);

  // The periodic surface of the same body: its normal operator (the FFT floor of a periodic
  // application), its 3 x 3 response and its stresses, all over the free surface's application.
  OperatorOptions periodic_options;
  periodic_options.method = Method::frf_split;
  periodic_options.boundary = Boundary::periodic;
  periodic_options.planning = Planning::measure;
  t0 = Clock::now();
  BuiltOperator periodic = make_operator(grid, body, periodic_options);
  const double periodic_setup = detail::seconds_since(t0);
  const double periodic_ms = median_ms([&] { periodic.op->apply(p, u); });
  rows.push_back(
      {n, "periodic surface", 0, periodic_setup, periodic_ms, periodic_ms / surface_ms, 0.0});
  rows.push_back(response_row(grid, body, p, qx, qy, surface_ms, true));
  add_stress_rows(grid, body, p, qx, qy, surface_ms, true, rows);
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Cost of a stress plane against a surface application"};
  std::string output = "bench/results/stress.csv";
  std::ptrdiff_t max_n = 1024;
  app.add("output", output, "CSV file to write").show_default();
  app.add("--max-n", max_n, "largest N (powers of 2 from 128)").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  std::ostringstream out;
  bench::write_machine_header(out);
  out << "# body = TiN 0.1 mm on steel, 4 mm domain; planes at 0.1 .. 0.8 mm; alpha = 16\n"
      << "# per_plane_over_surface = apply_ms / planes / (the surface apply_ms of the same N); "
         "for the 3 x 3 surface response (planes 0) apply_ms over the surface apply_ms\n"
      << "n,what,planes,setup_s,apply_ms,per_plane_over_surface,memory_mib\n";
  std::cout << out.str() << std::flush;
  for (std::ptrdiff_t n = 128; n <= max_n; n *= 2)
    for (const Row& r : measure(n)) {
      std::ostringstream line;
      line << r.n << ',' << r.what << ',' << r.planes << ',' << r.setup_s << ',' << r.apply_ms
           << ',' << r.per_plane_over_surface << ',' << r.memory_mib << '\n';
      std::cout << line.str() << std::flush;
      out << line.str();
    }
  out << "# peak_rss_mib = " << bench::peak_rss_mb() << "\n";
  std::cout << "# peak_rss_mib = " << bench::peak_rss_mb() << "\n";
  bench::write_text_file(output, out.str());
  return 0;
}
