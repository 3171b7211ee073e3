// Speed of one DC-FFT application (DcfftOperator, pruned padded transforms) against the bare FFTW
// pipeline it replaces: r2c of the full zero-padded (2N)^2 array, complex multiply, c2r, with the
// same planner flags (FFTW_MEASURE). Also direct summation vs DC-FFT on small grids, 1 vs 2
// threads, setup times and the peak RSS of a 2048^2 run. Prints "# key = value" headers and CSV
// rows, and writes them to bench/results/dcfft.csv (or the path given as first argument).
//
// Usage: bench_dcfft [output.csv] [max_n]      (max_n default 2048)
//        bench_dcfft --rss N                   (peak RSS of one N^2 DC-FFT run, nothing else)
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/bench_report.hpp"
#include "convolution/dcfft_operator.hpp"
#include "convolution/direct_operator.hpp"
#include "convolution/fftw_plan.hpp"
#include "convolution/influence_kernel.hpp"
#include "core/norms.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double e_star = 2.3e11;  // Pa (steel)

struct Timing {
  double min_ms;
  double median_ms;
  int reps;
};

// Runs `f` once to warm up, then repeatedly for about `budget_s` seconds (5 to 101 times); the
// median is robust to the other processes sharing the machine.
Timing time_it(const std::function<void()>& f, double budget_s = 1.5) {
  f();
  const auto t0 = Clock::now();
  f();
  const double once = std::chrono::duration<double>(Clock::now() - t0).count();
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 5, 101);
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(reps));
  for (int r = 0; r < reps; ++r) {
    const auto s = Clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
  }
  std::sort(ms.begin(), ms.end());
  return {ms.front(), ms[ms.size() / 2], reps};
}

coatfft::Field random_pressure(std::ptrdiff_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(0.0, 1e9);
  coatfft::Field p(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i) p(i, j) = dist(rng);
  return p;
}

// The bare FFTW pipeline on the full padded array: out-of-place 2-D r2c, multiply by the kernel's
// half spectrum, 2-D c2r. Its cropped output is the unpruned DC-FFT result, used for the error.
class BarePadded {
 public:
  BarePadded(const coatfft::InfluenceKernel& kernel, int threads)
      : n_(kernel.grid().nx()),
        m_(2 * n_),
        h_(n_ + 1),
        real_(static_cast<std::size_t>(m_ * m_)),
        spec_(static_cast<std::size_t>(m_ * h_)),
        kernel_(static_cast<std::size_t>(m_ * h_)) {
    const int m = static_cast<int>(m_);
    const auto t0 = Clock::now();
    r2c_ = coatfft::FftwPlan::create(threads, [&] {
      return fftw_plan_dft_r2c_2d(m, m, real_.data(), spec_.data(), FFTW_MEASURE);
    });
    c2r_ = coatfft::FftwPlan::create(threads, [&] {
      return fftw_plan_dft_c2r_2d(m, m, spec_.data(), real_.data(), FFTW_MEASURE);
    });
    plan_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    std::copy_n(kernel.wrapped().data(), m_ * m_, real_.data());
    r2c_.execute();
    const double scale = 1.0 / static_cast<double>(m_ * m_);
    auto* k = coatfft::as_complex(kernel_.data());
    const auto* s = coatfft::as_complex(spec_.data());
    for (std::ptrdiff_t q = 0; q < m_ * h_; ++q) k[q] = s[q] * scale;
  }

  void load(const coatfft::Field& p) {
    std::fill_n(real_.data(), m_ * m_, 0.0);
    for (std::ptrdiff_t j = 0; j < n_; ++j) std::copy_n(&p(0, j), n_, real_.data() + j * m_);
  }

  // The timed part: r2c, multiply, c2r (no copies in or out).
  void run() {
    r2c_.execute();
    auto* s = coatfft::as_complex(spec_.data());
    const auto* k = coatfft::as_complex(kernel_.data());
    for (std::ptrdiff_t q = 0; q < m_ * h_; ++q) s[q] *= k[q];
    c2r_.execute();
  }

  coatfft::Field crop() const {
    coatfft::Field u(n_, n_);
    for (std::ptrdiff_t j = 0; j < n_; ++j) std::copy_n(real_.data() + j * m_, n_, &u(0, j));
    return u;
  }

  double plan_ms() const { return plan_ms_; }

 private:
  std::ptrdiff_t n_, m_, h_;
  coatfft::FftwRealBuffer real_;
  coatfft::FftwComplexBuffer spec_;
  coatfft::FftwComplexBuffer kernel_;
  coatfft::FftwPlan r2c_;
  coatfft::FftwPlan c2r_;
  double plan_ms_ = 0.0;
};

struct Row {
  std::string method;
  std::ptrdiff_t n;
  int threads;
  double plan_ms;
  Timing t;
  double ratio;  // median / median of the bare pipeline at the same N and threads (0: n/a)
  double err_l2;
  double err_inf;
};

std::string csv(const Row& r) {
  std::ostringstream os;
  os.precision(6);
  os << r.method << ',' << r.n << ',' << r.threads << ',' << r.plan_ms << ',' << r.t.min_ms << ','
     << r.t.median_ms << ',' << r.ratio << ',' << r.err_l2 << ',' << r.err_inf;
  return os.str();
}

// Times `f` and `g` alternately (one warm-up each, then about `budget_s` seconds, 5 to 101
// pairs), so that both see the same load from other processes on a shared machine.
std::pair<Timing, Timing> time_pair(const std::function<void()>& f, const std::function<void()>& g,
                                    double budget_s = 3.0) {
  const auto t0 = Clock::now();
  f();
  g();
  const double once = std::chrono::duration<double>(Clock::now() - t0).count();
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 5, 101);
  std::vector<double> tf, tg;
  for (int r = 0; r < reps; ++r) {
    auto s = Clock::now();
    f();
    tf.push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
    s = Clock::now();
    g();
    tg.push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
  }
  std::sort(tf.begin(), tf.end());
  std::sort(tg.begin(), tg.end());
  return {{tf.front(), tf[tf.size() / 2], reps}, {tg.front(), tg[tg.size() / 2], reps}};
}

void dcfft_vs_bare(std::ptrdiff_t n, int threads, std::vector<Row>& rows, std::ostream& log) {
  const coatfft::Grid grid(n, n, 2e-3, 2e-3);
  const coatfft::Field p = random_pressure(n, 42u);
  coatfft::Field u;
  Row dc{"dcfft", n, threads, 0, {}, 0, 0, 0};
  Row bare{"bare_fftw_padded", n, threads, 0, {}, 1.0, 0, 0};
  coatfft::DcfftOperator op(coatfft::love_kernel(grid, e_star), coatfft::Planning::measure,
                            threads);
  dc.plan_ms = op.setup_seconds() * 1e3;
  BarePadded b(coatfft::love_kernel(grid, e_star), threads);
  b.load(p);
  bare.plan_ms = b.plan_ms();
  std::tie(dc.t, bare.t) = time_pair([&] { op.apply(p, u); }, [&] { b.run(); });
  b.load(p);
  b.run();
  const coatfft::Field plain = b.crop();
  dc.err_l2 = coatfft::rel_l2(u, plain);
  dc.err_inf = coatfft::rel_linf(u, plain);
  dc.ratio = dc.t.median_ms / bare.t.median_ms;
  rows.push_back(dc);
  rows.push_back(bare);
  log << csv(dc) << '\n' << csv(bare) << std::endl;
}

// Peak RSS of a child process that builds and applies one N^2 DcfftOperator and nothing else.
double child_peak_rss_mb(const char* self, std::ptrdiff_t n) {
  const std::string cmd = std::string(self) + " --rss " + std::to_string(n);
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return -1.0;
  char line[256];
  double mb = -1.0;
  while (std::fgets(line, sizeof line, pipe) != nullptr)
    std::sscanf(line, "# peak_rss_MB = %lf", &mb);
  pclose(pipe);
  return mb;
}

void direct_vs_dcfft(std::ptrdiff_t n, std::vector<Row>& rows, std::ostream& log) {
  const coatfft::Grid grid(n, n, 2e-3, 2e-3);
  const auto kernel = coatfft::love_kernel(grid, e_star);
  const coatfft::Field p = random_pressure(n, 7u);
  coatfft::DirectOperator direct(kernel);
  coatfft::DcfftOperator dcfft(kernel, coatfft::Planning::measure);
  coatfft::Field ud;
  coatfft::Field uf;
  Row rd{"direct", n, 1, 0, time_it([&] { direct.apply(p, ud); }, 1.0), 0, 0, 0};
  Row rf{"dcfft_small",
         n,
         1,
         dcfft.setup_seconds() * 1e3,
         time_it([&] { dcfft.apply(p, uf); }),
         0,
         coatfft::rel_l2(uf, ud),
         coatfft::rel_linf(uf, ud)};
  rd.ratio = rd.t.median_ms / rf.t.median_ms;  // speed-up of DC-FFT over direct
  rows.push_back(rd);
  rows.push_back(rf);
  log << csv(rd) << '\n' << csv(rf) << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 3 && std::string(argv[1]) == "--rss") {
      const std::ptrdiff_t n = std::stol(argv[2]);
      const coatfft::Grid grid(n, n, 2e-3, 2e-3);
      const coatfft::Field p = random_pressure(n, 42u);
      coatfft::DcfftOperator op(coatfft::love_kernel_quarter(grid, e_star),
                                coatfft::Planning::measure);
      coatfft::Field u = op.apply(p);
      std::cout << "# N = " << n << "\n# peak_rss_MB = " << coatfft::bench::peak_rss_mb()
                << "\n# setup_s = " << op.setup_seconds() << "\n";
      return 0;
    }
    const std::string out_path =
        argc > 1 ? argv[1] : std::string(COATFFT_SOURCE_DIR) + "/bench/results/dcfft.csv";
    const std::ptrdiff_t max_n = argc > 2 ? std::stol(argv[2]) : 2048;

    std::ostringstream header;
    header << "# bench = bench_dcfft\n";
    coatfft::bench::write_machine_header(header);
    header
        << "# planner = FFTW_MEASURE (both pipelines)\n"
        << "# timing = median and min of repeated single applications, after one warm-up\n"
        << "# bare = 2-D r2c of the full (2N)^2 padded array + complex multiply + 2-D c2r, "
           "no copies\n"
        << "# ratio = dcfft median / bare median (same N, threads); for direct rows: direct "
           "median / dcfft median\n"
        << "# errors = dcfft vs bare padded result (dcfft rows) or vs direct (dcfft_small)\n"
        << "method,N,threads,plan_ms,apply_ms_min,apply_ms_median,ratio,rel_err_l2,rel_err_inf\n";
    std::cout << header.str() << std::flush;
    std::vector<Row> rows;
    for (std::ptrdiff_t n : {256, 512, 1024, 2048})
      if (n <= max_n) dcfft_vs_bare(n, 1, rows, std::cout);
    for (std::ptrdiff_t n : {1024, 2048})
      if (n <= max_n) dcfft_vs_bare(n, 2, rows, std::cout);
    for (std::ptrdiff_t n : {32, 64}) direct_vs_dcfft(n, rows, std::cout);

    std::ostringstream body;
    for (const Row& r : rows) body << csv(r) << '\n';
    std::ostringstream footer;
    footer << "# peak_rss_MB_dcfft_only_" << max_n << " = " << child_peak_rss_mb(argv[0], max_n)
           << "   (child process: love_kernel_quarter + DcfftOperator + p + u, FFTW_MEASURE)\n";
    footer << "# peak_rss_MB_this_run = " << coatfft::bench::peak_rss_mb()
           << "   (includes the bare pipeline)\n";
    std::cout << footer.str();
    coatfft::bench::write_text_file(out_path, header.str() + body.str() + footer.str());
    std::cout << "written " << out_path << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_dcfft: " << e.what() << "\n";
    return 1;
  }
}
