// The summary step of a [stress] run (scene/scene_stress.cpp: the planes' maxima for
// summary.json, and the arrays of the files asked for) against the planes' own application, side
// by side in one run: a Hertz pressure (p0 = 1 GPa, a = L / 6) on 0.1 mm of TiN on steel, 8 planes
// from 0.1 a to 2 a deep and the interface from both sides, on N x N grids, free (alpha = 4) and
// periodic, one thread. Per row: the application's time (StressOperator, summary.json's
// apply_seconds), the summary step's (maxima_seconds) with every array assembled and with none
// (fields = ["summary"]), and the same maxima found with the iterative eigenvalues of every cell
// (the summary step before it screened the cells by the closed form; timed here on the same
// planes, and its maxima required equal to the summary's).
// Prints `# key = value` headers and CSV rows, and writes them to bench/results/stress_summary.csv.
//   bench_stress_summary [OUTPUT] [--sizes N ...]
#include <algorithm>
#include <array>
#include <chrono>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"
#include "scene/scene_stress.hpp"
#include "stress/stress_invariants.hpp"
#include "stress/stress_operator.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

constexpr double kLength = 3e-3;

LayerStack body() {
  return LayerStack({{Material(400e9, 0.25), 1e-4, Interface::bonded}}, Material(210e9, 0.3));
}

scene::StressSpec spec(Boundary boundary) {
  scene::StressSpec s;
  const double a = kLength / 6;
  for (int k = 1; k <= 8; ++k) s.depths.push_back(a * (0.1 + 1.9 * (k - 1) / 7.0));
  s.alpha = 4;
  s.boundary = boundary;
  return s;
}

// The maxima with the eigenvalues of every cell, as the summary step computed them before: von
// Mises' stress, the largest principal stress and Tresca's, over every plane, and its time.
struct EveryCell {
  double mises = 0, tensile = -1e300, tresca = 0, seconds = 0;
  double apply_seconds = 0;  // the planes' application alone, the median of 5
};

EveryCell every_cell(const scene::StressSpec& s, const Grid& g, const Field& p) {
  const scene::StressPlanes planes = scene::stress_planes(s, body());
  StressOperatorOptions options;
  options.kernel.alpha = s.alpha;
  options.boundary = s.boundary;
  options.sides = planes.sides;
  const auto op = make_stress_operator(g, body(), planes.depths, options);
  std::vector<PlaneStress> stress;
  EveryCell e;
  std::vector<double> applies;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = Clock::now();
    op->apply(p, nullptr, nullptr, stress);
    applies.push_back(detail::seconds_since(t0));
  }
  e.apply_seconds = detail::median(applies);
  const auto start = Clock::now();
  for (const PlaneStress& plane : stress)
    for (Eigen::Index k = 0; k < plane[0].size(); ++k) {
      const StressVector t{plane[0](k), plane[1](k), plane[2](k),
                           plane[3](k), plane[4](k), plane[5](k)};
      const std::array<double, 3> principal = principal_stresses(t);
      e.mises = std::max(e.mises, von_mises(t));
      e.tensile = std::max(e.tensile, principal[0]);
      e.tresca = std::max(e.tresca, 0.5 * (principal[0] - principal[2]));
    }
  e.seconds = detail::seconds_since(start);
  return e;
}

std::string measure(std::ptrdiff_t n, Boundary boundary) {
  const Grid g(n, n, kLength, kLength);
  const Field p = hertz_pressure(g, 1e9, kLength / 6, Sampling::cell_average);
  const scene::StressSpec s = spec(boundary);
  scene::ProgressObserver silent;
  const scene::StressRun all = scene::compute_stress(s, body(), g, p, {}, 1, silent);
  const scene::StressRun summary_only = scene::compute_stress(
      s, body(), g, p, {}, 1, silent, {false, false, false, false, false, false});
  const EveryCell e = every_cell(s, g, p);
  const double apply = e.apply_seconds;
  const double maxima_all = all.summary["maxima_seconds"].get<double>();
  const double maxima_summary = summary_only.summary["maxima_seconds"].get<double>();
  const double every_cell = e.seconds;
  // The bounded maxima are those of every cell's eigenvalues, and the same without the arrays.
  for (const auto& [key, value] : {std::pair{"max_von_mises", e.mises},
                                   {"max_principal_tensile", e.tensile},
                                   {"max_tresca", e.tresca}})
    if (all.summary[key]["value"].get<double>() != value ||
        summary_only.summary[key] != all.summary[key])
      throw Error(detail::concat("bench: ", key, " differs from every cell's"));
  std::ostringstream row;
  row.precision(4);
  row << n << "," << (boundary == Boundary::periodic ? "periodic" : "free") << ","
      << all.summary["planes"].get<int>() << "," << apply << "," << maxima_all << ","
      << maxima_summary << "," << every_cell << "," << maxima_all / apply << ","
      << maxima_summary / apply << "," << every_cell / apply << "\n";
  return row.str();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"A [stress] run's summary step against its planes"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/stress_summary.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512, 1024};
  app.add("--sizes", sizes, "Grid sizes N").comma_separated().show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_stress_summary (a [stress] run's summary step against its "
           "planes)\n";
    coatfft::bench::write_machine_header(out);
    out << "# Hertz p0 = 1 GPa, a = L/6 on 0.1 mm TiN on steel, L = 3 mm; 8 planes 0.1a..2a and "
           "the interface from both sides; alpha = 4 (free); one thread\n"
        << "# apply_s: the planes' application (median of 5); maxima_all_s: the summary step with "
           "every array "
           "assembled; maxima_summary_s: with none (fields = [\"summary\"]); every_cell_s: the "
           "maxima with the eigenvalues of every cell (the step before)\n"
        << "N,boundary,planes,apply_s,maxima_all_s,maxima_summary_s,every_cell_s,"
           "maxima_all_over_apply,maxima_summary_over_apply,every_cell_over_apply\n";
    std::cout << out.str() << std::flush;
    for (const std::ptrdiff_t n : sizes)
      for (const Boundary b : {Boundary::periodic, Boundary::free}) {
        const std::string row = measure(n, b);
        std::cout << row << std::flush;
        out << row;
      }
    coatfft::bench::write_text_file(out_path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_stress_summary: " << e.what() << "\n";
    return 1;
  }
}
