// Cost of one FRF evaluation H(k) for the homogeneous half-space, one coating (closed forms,
// bonded and frictionless), the n-layer recursion with one coating (same stacks, for comparison)
// and a 5-layer stack. The wavenumbers sweep k h_top over 1e-4..1e4 log-uniformly, so both the
// thin-layer (propagator) and thick-layer (decaying basis) branches are timed in proportion.
// Prints "# key = value" headers and CSV rows, and writes them to bench/results/frf_eval.csv
// (or OUTPUT).
//   bench_frf [OUTPUT]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "core/detail/timing.hpp"
#include "frf/coated_frf.hpp"
#include "frf/half_space_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using coatfft::Interface;
using coatfft::LayerStack;
using coatfft::Material;

struct Case {
  std::string label;
  int nb_coatings;
  std::unique_ptr<coatfft::Frf> frf;
};

struct Result {
  double ns_min;
  double ns_median;
  double checksum;
};

// 21 repetitions of a sweep over all wavenumbers; min and median ns per evaluation.
Result time_case(const coatfft::Frf& frf, const std::vector<double>& ks) {
  std::vector<double> ns;
  double checksum = 0.0;
  for (int rep = 0; rep < 21; ++rep) {
    double sum = 0.0;
    const auto t0 = Clock::now();
    for (double k : ks) sum += frf(k) * k;
    const double s = coatfft::detail::seconds_since(t0);
    ns.push_back(1e9 * s / static_cast<double>(ks.size()));
    checksum = sum;  // keeps the loop from being optimised away
  }
  return {*std::min_element(ns.begin(), ns.end()), coatfft::detail::median(ns), checksum};
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Nanoseconds per FRF evaluation H(k)"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/frf_eval.csv";
  app.add("output", out_path, "CSV file").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  const Material tin(4e11, 0.25), steel(2.1e11, 0.3), polymer(3e9, 0.4), dlc(2e11, 0.22);
  const double h = 1e-6;  // top coating thickness [m]
  std::vector<Case> cases;
  cases.push_back({"half_space", 0, std::make_unique<coatfft::HalfSpaceFrf>(steel)});
  cases.push_back(
      {"coated_bonded", 1, std::make_unique<coatfft::CoatedFrf>(tin, h, steel, Interface::bonded)});
  cases.push_back({"coated_frictionless", 1,
                   std::make_unique<coatfft::CoatedFrf>(tin, h, steel, Interface::frictionless)});
  cases.push_back(
      {"multilayer_bonded", 1,
       std::make_unique<coatfft::MultilayerFrf>(LayerStack({{tin, h, Interface::bonded}}, steel))});
  cases.push_back({"multilayer_frictionless", 1,
                   std::make_unique<coatfft::MultilayerFrf>(
                       LayerStack({{tin, h, Interface::frictionless}}, steel))});
  cases.push_back({"multilayer_5", 5,
                   std::make_unique<coatfft::MultilayerFrf>(
                       LayerStack({{tin, h, Interface::bonded},
                                   {dlc, 0.5 * h, Interface::bonded},
                                   {polymer, 2 * h, Interface::frictionless},
                                   {tin, 0.3 * h, Interface::bonded},
                                   {dlc, 1.5 * h, Interface::bonded}},
                                  steel))});

  constexpr int nb_k = 4096;
  std::vector<double> ks;
  for (int i = 0; i < nb_k; ++i) ks.push_back(1e-4 / h * std::pow(1e8, i / (nb_k - 1.0)));

  std::ostringstream os;
  os << "# benchmark = bench_frf (ns per H(k) evaluation)\n";
  coatfft::bench::write_machine_header(os);
  os << "# wavenumbers = " << nb_k << " log-spaced, k h_top in [1e-4, 1e4], h_top = " << h
     << " m\n";
  os << "# repetitions = 21 sweeps; min and median over sweeps\n";
  os << "frf,nb_coatings,nb_k,ns_per_eval_min,ns_per_eval_median,checksum\n";
  for (const auto& c : cases) {
    const Result r = time_case(*c.frf, ks);
    os << c.label << "," << c.nb_coatings << "," << nb_k << "," << r.ns_min << "," << r.ns_median
       << "," << r.checksum << "\n";
  }
  std::cout << os.str();
  coatfft::bench::write_text_file(out_path, os.str());
  return 0;
}
