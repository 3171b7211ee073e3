// One DC-FFT application on grids whose doubled size 2N is a poor FFT length (N = 127, 511: 2N =
// 2 x 127, 2 x 7 x 73) next to the power of two above (N = 128, 512), for Love's kernel (dcfft)
// and the split kernel of a coated body (frf-split): DcfftOperator pads to the smallest even
// 7-smooth length >= 2N - 1 (core/detail/fft_size.hpp), so an odd N should cost about what N + 1
// does. The old padding to exactly 2N is timed too: the same kernel handed over as its spectrum on
// the 2N lattice (the spectrum form keeps M = 2N). All operators of one (method, N pair) are
// applied in turn, round after round, so that they see the same load; medians per operator. Prints
// "# key = value" headers and CSV rows and writes them to bench/results/fft_sizes.csv (or OUTPUT).
//   bench_fft_sizes [OUTPUT] [--budget 4] [--threads 1]
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/norms.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

constexpr double side = 2e-3;  // m, square domain for every N (the cells shrink as N grows)

const Material steel(210e9, 0.3);
// A 1 um TiN-like coating (600 GPa, 0.25) bonded on steel.
const LayerStack coated({Coating{Material(600e9, 0.25), 1e-6, Interface::bonded}}, steel);

InfluenceKernel make_kernel(Method method, std::ptrdiff_t n) {
  const Grid grid(n, n, side, side);
  if (method == Method::dcfft) return love_kernel(grid, steel.plane_strain_modulus());
  return split_frf_kernel(grid, *make_frf(coated));
}

// The same kernel as its spectrum on the 2N lattice: the 2-D DCT-I (REDFT00) of the coefficient
// quarter, which is what DcfftOperator padded to 2N computed before fast sizes. A
// DcfftOperator of this form pads to exactly 2N: the old padding, for reference.
InfluenceKernel on_2n_lattice(const InfluenceKernel& k) {
  const Field& q = k.quarter();
  Field s(q.rows(), q.cols());
  const FftwPlan dct = FftwPlan::create(1, [&] {
    return fftw_plan_r2r_2d(static_cast<int>(q.cols()), static_cast<int>(q.rows()),
                            const_cast<double*>(q.data()), s.data(), FFTW_REDFT00, FFTW_REDFT00,
                            FFTW_ESTIMATE | FFTW_PRESERVE_INPUT);
  });
  dct.execute();
  return InfluenceKernel(k.grid(), InfluenceKernel::Form::spectrum, std::move(s), k.method());
}

Field random_pressure(std::ptrdiff_t n) {
  std::mt19937_64 rng(42u);
  std::uniform_real_distribution<double> dist(0.0, 1e9);
  Field p(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i) p(i, j) = dist(rng);
  return p;
}

struct Variant {
  std::string label;  // the CSV's method column
  std::ptrdiff_t n;
  BuiltOperator built;
  Field p;
  Field u;
  std::vector<double> seconds;
};

// Applies every variant once per round (one warm-up round first) for about `budget_s` seconds,
// 7 to 101 rounds; the medians are the variants' apply_s_median.
std::vector<double> time_round_robin(std::vector<Variant>& vs, double budget_s) {
  const auto t0 = Clock::now();
  for (Variant& v : vs) v.built.op->apply(v.p, v.u);
  const double once = detail::seconds_since(t0);
  const int rounds = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 7, 101);
  for (int r = 0; r < rounds; ++r)
    for (Variant& v : vs) {
      const auto s = Clock::now();
      v.built.op->apply(v.p, v.u);
      v.seconds.push_back(detail::seconds_since(s));
    }
  std::vector<double> medians;
  for (const Variant& v : vs) medians.push_back(detail::median(v.seconds));
  return medians;
}

// The CSV rows of one method at N odd = even - 1 (fast padding, then 2N padding) and N even, and
// a footer line with the largest relative difference of the two odd-N results.
void run_pair(Method method, std::ptrdiff_t even, const OperatorOptions& o, double budget_s,
              std::ostream& rows, std::ostream& footer) {
  const std::string name(to_string(method));
  const InfluenceKernel odd_kernel = make_kernel(method, even - 1);
  std::vector<Variant> vs;
  vs.push_back({name, even - 1, make_operator(odd_kernel, o), random_pressure(even - 1), {}, {}});
  vs.push_back({name + "_pad2n",
                even - 1,
                make_operator(on_2n_lattice(odd_kernel), o),
                random_pressure(even - 1),
                {},
                {}});
  vs.push_back(
      {name, even, make_operator(make_kernel(method, even), o), random_pressure(even), {}, {}});
  const std::vector<double> medians = time_round_robin(vs, budget_s);
  for (std::size_t i = 0; i < vs.size(); ++i) {
    std::ostringstream line;
    line.precision(6);
    line << vs[i].label << ',' << vs[i].n << ',' << vs[i].built.report.fft_nx << ',' << medians[i]
         << ',' << medians[i] / medians[2] << '\n';
    rows << line.str();
    std::cout << line.str() << std::flush;
  }
  footer << "# rel_diff_fast_vs_pad2n_" << name << "_" << even - 1 << " = "
         << rel_linf(vs[0].u, vs[1].u) << "   (max |u_fast - u_2n| / max |u_2n|)\n";
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{
      "DC-FFT on awkward grid sizes (fast FFT padding) against the next power of two"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/fft_sizes.csv";
  app.add("output", out_path, "CSV file").show_default();
  double budget_s = 4.0;
  app.add("--budget", budget_s, "Seconds of timed rounds per (method, N pair)")
      .show_default()
      .range(0.0, 600.0);
  int threads = 1;
  app.add("--threads", threads, "Threads of apply()").show_default().range(1, 64);
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream header;
    header << "# bench = bench_fft_sizes\n";
    bench::write_machine_header(header);
    header << "# threads = " << threads << "\n"
           << "# planner = FFTW_MEASURE\n"
           << "# grid = N x N cells on a " << side << " m square, random pressure in [0, 1 GPa]\n"
           << "# kernels = dcfft: Love, steel (210 GPa, 0.3); frf-split: TiN (600 GPa, 0.25) "
              "1 um bonded on steel\n"
           << "# timing = median of single applications, the three operators of a (method, N "
              "pair) applied in turn each round, after one warm-up round\n"
           << "# padded = transform length per axis (make_operator's report.fft_nx); *_pad2n = "
              "the same kernel padded to exactly 2N (the layout before fast sizes)\n"
           << "# ratio_to_even = apply_s_median / that of the even N of the same method\n"
           << "method,n,padded,apply_s_median,ratio_to_even\n";
    std::cout << header.str() << std::flush;
    OperatorOptions o;
    o.planning = Planning::measure;
    o.threads = threads;
    std::ostringstream rows;
    std::ostringstream footer;
    for (const std::ptrdiff_t even : {128, 512})
      for (const Method method : {Method::dcfft, Method::frf_split})
        run_pair(method, even, o, budget_s, rows, footer);
    std::cout << footer.str();
    bench::write_text_file(out_path, header.str() + rows.str() + footer.str());
    std::cout << "written " << out_path << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_fft_sizes: " << e.what() << "\n";
    return 1;
  }
}
