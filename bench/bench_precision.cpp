// Single against double precision for the periodic operator
// (convolution/operators/periodic_operator.hpp): the time of one application (median of repeats,
// warm) in each precision and the ratio, under FFTW_ESTIMATE and FFTW_MEASURE plans (the latter on
// one and two threads), and the single-precision error: the largest difference from the double
// application relative to the largest displacement, on the displacement of a random (uniform [0,
// 1]) pressure, steel, N = 512 ... 4096; and the double operator's setup under each planning
// (FFTW's planning, with the kernel's one transform). Prints `# key = value` headers and CSV rows,
// and writes the same to bench/results/precision.csv (or OUTPUT).
//   bench_precision [OUTPUT] [--sizes N ...]
#include <chrono>
#include <exception>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "frf/half_space_frf.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

double median_apply_ms(PeriodicOperator& op, const Field& p, Field& u) {
  op.apply(p, u);  // warm-up
  std::vector<double> times;
  const int repeats = p.size() <= (1 << 22) ? 9 : 5;
  for (int k = 0; k < repeats; ++k) {
    const auto start = Clock::now();
    op.apply(p, u);
    times.push_back(1e3 * detail::seconds_since(start));
  }
  return detail::median(times);
}

Field random_pressure(std::ptrdiff_t n) {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Field p(n, n);
  for (std::ptrdiff_t k = 0; k < p.size(); ++k) p.data()[k] = uniform(engine);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Single against double precision for the periodic operator"};
  std::string path = "bench/results/precision.csv";
  app.add("output", path, "CSV file").show_default();
  std::vector<std::ptrdiff_t> sizes = {512, 1024, 2048, 4096};
  app.add("--sizes", sizes, "grid sizes N (N x N cells)").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::ostringstream out;
    out << "# benchmark = bench_precision (periodic operator, one application, steel)\n";
    bench::write_machine_header(out);
    out << "# fields are double outside the transforms in both precisions\n"
        << "# error = max |u_single - u_double| / max |u_double| for a uniform [0, 1] random "
           "pressure\n"
        << "# double_setup_s: the double operator's construction (kernel spectrum and plans)\n"
        << "N,planning,threads,double_ms,single_ms,speedup,error,double_setup_s\n";
    std::cout << out.str() << std::flush;
    const HalfSpaceFrf frf(Material(210e9, 0.3));
    for (const std::ptrdiff_t n : sizes) {
      const Grid g(n, n, 1e-3, 1e-3);
      PeriodicKernelOptions o;
      o.threads = 2;
      const Field kernel = periodic_influence_kernel(g, frf, o);
      const Field p = random_pressure(n);
      for (const auto& [planning, threads] :
           {std::pair{Planning::estimate, 1}, {Planning::measure, 1}, {Planning::measure, 2}}) {
        const auto setup_start = Clock::now();
        PeriodicOperator exact(g, kernel, Method::dcfft, planning, Precision::double_precision,
                               threads);
        const double setup_s = detail::seconds_since(setup_start);
        PeriodicOperator single(g, kernel, Method::dcfft, planning, Precision::single, threads);
        Field u_exact, u_single;
        const double exact_ms = median_apply_ms(exact, p, u_exact);
        const double single_ms = median_apply_ms(single, p, u_single);
        const double error = (u_single - u_exact).abs().maxCoeff() / u_exact.abs().maxCoeff();
        std::ostringstream row;
        row.precision(4);
        row << n << "," << to_string(planning) << "," << threads << "," << exact_ms << ","
            << single_ms << "," << exact_ms / single_ms << "," << error << "," << setup_s << "\n";
        std::cout << row.str() << std::flush;
        out << row.str();
      }
    }
    bench::write_text_file(path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_precision: " << e.what() << "\n";
    return 1;
  }
}
