// Setup cost against application cost (issue 5: "the setup costs at most 3 applications at 1024^2
// for every method"). For each body, grid and method the setup is split into its parts
// (influence coefficients or FRF sampling, g(0), FFTW planning + kernel transform) and timed
// `reps` times, interleaved with applications of the operator it built (so that the load of the
// shared machine hits both alike); medians are reported with the ratio setup / apply.
// FFTW_ESTIMATE throughout. Prints "# key = value" headers and CSV rows and writes them to
// bench/results/setup.csv (or the path given as first argument).
//
// Usage: bench_setup [output.csv] [sizes, e.g. 512,1024,2048] [threads, e.g. 1,2] [reps] [alpha]
// (alpha, default 2, is the extension ratio of frf-spectral and frf-dcfft; at alpha = 4
// frf-dcfft's "kernel" is frf_influence_kernel: FRF sampling on the 4N lattice and its DCT-I.)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "convolution/dcfft_operator.hpp"
#include "convolution/frf_dcfft_operator.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "convolution/g0.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "frf/coated_frf.hpp"
#include "frf/half_space_frf.hpp"
#include "materials/material.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using Clock = std::chrono::steady_clock;
using coatfft::Field;
using coatfft::bench::median;
using coatfft::bench::parse_int_list;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// One setup: its parts in seconds and the operator it built.
struct Setup {
  double kernel_s = 0.0;     // influence coefficients (dcfft, frf-dcfft, frf-split)
  double g0_s = 0.0;         // g(0) (frf-spectral, frf-dcfft)
  double transform_s = 0.0;  // operator constructor: FFTW plans + kernel transform (+ sampling)
  std::unique_ptr<coatfft::SurfaceOperator> op;
};

struct Body {
  std::string name;
  std::unique_ptr<coatfft::Frf> frf;
  double e_star = 0.0;  // > 0 only for the homogeneous body (Love's kernel)
};

constexpr double length = 4e-3;  // domain side [m]

Setup run_setup(const std::string& method, const Body& body, const coatfft::Grid& grid,
                double alpha, int threads) {
  using namespace coatfft;
  Setup s;
  const double dkx = 2.0 * std::numbers::pi / (alpha * grid.lx());
  const double dky = 2.0 * std::numbers::pi / (alpha * grid.ly());
  if (method == "dcfft") {
    auto t = Clock::now();
    const EvenInfluenceKernel k = love_kernel_quarter(grid, body.e_star, threads);
    s.kernel_s = seconds_since(t);
    t = Clock::now();
    s.op = std::make_unique<DcfftOperator>(k, Planning::estimate, threads);
    s.transform_s = seconds_since(t);
  } else if (method == "frf-spectral") {
    auto t = Clock::now();
    const G0Result g0 = compute_g0(*body.frf, dkx, dky, G0Method::regularized);
    s.g0_s = seconds_since(t);
    t = Clock::now();
    s.op = std::make_unique<FrfSpectralOperator>(grid, *body.frf, alpha, g0, Planning::estimate,
                                                 threads);
    s.transform_s = seconds_since(t);
  } else if (method == "frf-dcfft") {
    auto t = Clock::now();
    const G0Result g0 = compute_g0(*body.frf, dkx, dky, G0Method::regularized);
    s.g0_s = seconds_since(t);
    t = Clock::now();
    // At alpha = 2 the FRF samples are the kernel's spectrum (frf_dcfft_operator.hpp): "kernel"
    // is the sampling, "transform" DcfftOperator's constructor (plans, spectrum layout). At
    // other alpha "kernel" is frf_influence_kernel (sampling, inverse DCT, wrap-around copy).
    auto op = frf_dcfft_operator(grid, *body.frf, alpha, g0, Planning::estimate, threads);
    s.transform_s = op->setup_seconds();
    s.kernel_s = seconds_since(t) - s.transform_s;
    s.op = std::move(op);
  } else {  // frf-split
    SplitKernelOptions o;
    o.threads = threads;
    auto t = Clock::now();
    const EvenInfluenceKernel k = split_frf_kernel_quarter(grid, *body.frf, o);
    s.kernel_s = seconds_since(t);
    t = Clock::now();
    s.op = std::make_unique<DcfftOperator>(k, Planning::estimate, threads);
    s.transform_s = seconds_since(t);
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    using namespace coatfft;
    const std::string out_path =
        argc > 1 ? argv[1] : std::string(COATFFT_SOURCE_DIR) + "/bench/results/setup.csv";
    const std::vector<int> sizes = parse_int_list(argc > 2 ? argv[2] : "512,1024");
    const std::vector<int> thread_list = parse_int_list(argc > 3 ? argv[3] : "1,2");
    const int reps = argc > 4 ? std::max(1, std::atoi(argv[4])) : 5;
    const double alpha = argc > 5 ? std::atof(argv[5]) : 2.0;
    constexpr int applies_per_rep = 3;

    const Material steel(210e9, 0.3);
    const Material tin(600e9, 0.25);
    std::vector<Body> bodies;
    bodies.push_back(
        {"steel", std::make_unique<HalfSpaceFrf>(steel), steel.plane_strain_modulus()});
    bodies.push_back({"tin50um_on_steel",
                      std::make_unique<CoatedFrf>(tin, 50e-6, steel, Interface::bonded), 0.0});

    std::ostringstream csv;
    csv << "# bench_setup: setup (coefficients/sampling + g0 + plans/kernel transform) vs one "
           "application, medians of interleaved runs\n";
    coatfft::bench::write_machine_header(csv);
    csv << "# planning = FFTW_ESTIMATE\n";
    csv << "# domain = " << length << " m square, alpha = " << alpha << "\n";
    csv << "# bodies = steel (E 210 GPa, nu 0.3); TiN (600 GPa, 0.25) 50 um bonded on steel\n";
    csv << "# reps = " << reps << " setups, " << applies_per_rep << " applications after each\n";
    csv << "body,method,n,threads,kernel_s,g0_s,transform_s,setup_s,apply_s,ratio\n";
    std::cout << csv.str() << std::flush;

    const std::vector<std::string> methods = {"dcfft", "frf-spectral", "frf-dcfft", "frf-split"};
    for (const int n : sizes) {
      const Grid grid(n, n, length, length);
      Field p(n, n);
      for (std::ptrdiff_t j = 0; j < n; ++j)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
          const double r2 = (grid.x(i) * grid.x(i) + grid.y(j) * grid.y(j)) / 1e-6;
          p(i, j) = r2 < 1.0 ? 1e9 * std::sqrt(1.0 - r2) : 0.0;
        }
      Field u;
      for (const Body& body : bodies)
        for (const int threads : thread_list)
          for (const std::string& method : methods) {
            if (method == "dcfft" && body.e_star <= 0.0) continue;  // Love: homogeneous only
            std::vector<double> kernel_s, g0_s, transform_s, setup_s, apply_s;
            for (int r = 0; r < reps; ++r) {
              Setup s = run_setup(method, body, grid, alpha, threads);
              kernel_s.push_back(s.kernel_s);
              g0_s.push_back(s.g0_s);
              transform_s.push_back(s.transform_s);
              setup_s.push_back(s.kernel_s + s.g0_s + s.transform_s);
              for (int a = 0; a < applies_per_rep; ++a) {
                const auto t = Clock::now();
                s.op->apply(p, u);
                apply_s.push_back(seconds_since(t));
              }
            }
            std::ostringstream row;
            const double st = median(setup_s);
            const double ap = median(apply_s);
            row << body.name << ',' << method << ',' << n << ',' << threads << ','
                << median(kernel_s) << ',' << median(g0_s) << ',' << median(transform_s) << ','
                << st << ',' << ap << ',' << st / ap << '\n';
            std::cout << row.str() << std::flush;
            csv << row.str();
          }
    }
    coatfft::bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_setup: " << e.what() << '\n';
    return 1;
  }
}
