// Speed of one DC-FFT application (pruned padded transforms) against the bare FFTW pipeline it
// replaces: r2c of the full zero-padded (2N)^2 array, complex multiply, c2r, with the same planner
// flags (FFTW_MEASURE). Also direct summation vs DC-FFT on small grids, 1 vs 2 threads, setup
// times and the peak RSS of a max_n^2 run (a child process doing only that). Prints
// "# key = value" headers and CSV rows, and writes them to bench/results/dcfft.csv (or OUTPUT).
//   bench_dcfft [OUTPUT] [--max-n N]
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <complex>
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
#include "bench/child_process.hpp"
#include "bench/command_line.hpp"
#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/norms.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double e_star = 2.3e11;  // Pa (steel)

// DC-FFT (or, with Method::direct, direct summation) on Love's kernel of E* = e_star.
coatfft::BuiltOperator love_operator(const coatfft::InfluenceKernel& kernel, coatfft::Method method,
                                     int threads = 1) {
  coatfft::OperatorOptions o;
  o.method = method;
  o.planning = coatfft::Planning::measure;
  o.threads = threads;
  return coatfft::make_operator(kernel, o);
}

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
  const double once = coatfft::detail::seconds_since(t0);
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 5, 101);
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(reps));
  for (int r = 0; r < reps; ++r) {
    const auto s = Clock::now();
    f();
    ms.push_back(1e3 * coatfft::detail::seconds_since(s));
  }
  return {*std::min_element(ms.begin(), ms.end()), coatfft::detail::median(ms), reps};
}

coatfft::Field random_pressure(std::ptrdiff_t n, unsigned stream) {
  std::mt19937_64 rng(stream);
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
    plan_ms_ = 1e3 * coatfft::detail::seconds_since(t0);
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
  const double once = coatfft::detail::seconds_since(t0);
  const int reps = std::clamp(static_cast<int>(budget_s / std::max(once, 1e-9)), 5, 101);
  std::vector<double> tf, tg;
  for (int r = 0; r < reps; ++r) {
    auto s = Clock::now();
    f();
    tf.push_back(1e3 * coatfft::detail::seconds_since(s));
    s = Clock::now();
    g();
    tg.push_back(1e3 * coatfft::detail::seconds_since(s));
  }
  const auto summary = [reps](const std::vector<double>& ms) {
    return Timing{*std::min_element(ms.begin(), ms.end()), coatfft::detail::median(ms), reps};
  };
  return {summary(tf), summary(tg)};
}

void dcfft_vs_bare(std::ptrdiff_t n, int threads, std::vector<Row>& rows, std::ostream& log) {
  const coatfft::Grid grid(n, n, 2e-3, 2e-3);
  const coatfft::Field p = random_pressure(n, 42u);
  coatfft::Field u;
  Row dc{"dcfft", n, threads, 0, {}, 0, 0, 0};
  Row bare{"bare_fftw_padded", n, threads, 0, {}, 1.0, 0, 0};
  const coatfft::InfluenceKernel kernel = coatfft::love_kernel(grid, e_star);
  const coatfft::BuiltOperator op = love_operator(kernel, coatfft::Method::dcfft, threads);
  dc.plan_ms = op.report.setup_seconds * 1e3;
  BarePadded b(kernel, threads);
  b.load(p);
  bare.plan_ms = b.plan_ms();
  std::tie(dc.t, bare.t) = time_pair([&] { op.op->apply(p, u); }, [&] { b.run(); });
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

// Builds and applies one N^2 DC-FFT operator and nothing else: what the child of
// child_peak_rss_mb runs (this program with --rss N).
int rss_child(std::ptrdiff_t n) {
  const coatfft::Grid grid(n, n, 2e-3, 2e-3);
  const coatfft::Field p = random_pressure(n, 42u);
  const coatfft::BuiltOperator op =
      love_operator(coatfft::love_kernel(grid, e_star), coatfft::Method::dcfft);
  const coatfft::Field u = op.op->apply(p);
  std::cout << "# N = " << n << "\n# setup_s = " << op.report.setup_seconds << "\n";
  return 0;
}

// Peak RSS [MiB] of a child process that builds and applies one N^2 DC-FFT operator and nothing
// else (wait4's rusage); -1 if it failed.
double child_peak_rss_mb(std::ptrdiff_t n) {
  const coatfft::bench::ChildOutcome out =
      coatfft::bench::run_child({coatfft::bench::self_executable(), "--rss", std::to_string(n)});
  return out.exit_code == 0 ? out.peak_rss_mb : -1.0;
}

void direct_vs_dcfft(std::ptrdiff_t n, std::vector<Row>& rows, std::ostream& log) {
  const coatfft::Grid grid(n, n, 2e-3, 2e-3);
  const auto kernel = coatfft::love_kernel(grid, e_star);
  const coatfft::Field p = random_pressure(n, 7u);
  const coatfft::BuiltOperator direct = love_operator(kernel, coatfft::Method::direct);
  const coatfft::BuiltOperator dcfft = love_operator(kernel, coatfft::Method::dcfft);
  coatfft::Field ud;
  coatfft::Field uf;
  Row rd{"direct", n, 1, 0, time_it([&] { direct.op->apply(p, ud); }, 1.0), 0, 0, 0};
  Row rf{"dcfft_small",
         n,
         1,
         dcfft.report.setup_seconds * 1e3,
         time_it([&] { dcfft.op->apply(p, uf); }),
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
  coatfft::bench::CommandLine app{
      "One DC-FFT application against the bare padded FFTW pipeline; direct summation"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/dcfft.csv";
  app.add("output", out_path, "CSV file").show_default();
  std::ptrdiff_t max_n = 2048;
  app.add("--max-n", max_n, "Largest grid (also the size of the peak-RSS run)")
      .show_default()
      .range(std::ptrdiff_t{2}, std::ptrdiff_t{1} << 16);
  std::ptrdiff_t rss_n = 0;
  app.add("--rss", rss_n,
          "Internal: only build and apply one N^2 operator (the child "
          "whose peak RSS is reported)")
      .hidden();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    if (rss_n > 0) return rss_child(rss_n);
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
    for (const std::ptrdiff_t n : {256, 512, 1024, 2048})
      if (n <= max_n) dcfft_vs_bare(n, 1, rows, std::cout);
    for (const std::ptrdiff_t n : {1024, 2048})
      if (n <= max_n) dcfft_vs_bare(n, 2, rows, std::cout);
    for (const std::ptrdiff_t n : {32, 64}) direct_vs_dcfft(n, rows, std::cout);

    std::ostringstream body;
    for (const Row& r : rows) body << csv(r) << '\n';
    std::ostringstream footer;
    footer << "# peak_rss_MB_dcfft_only_" << max_n << " = " << child_peak_rss_mb(max_n)
           << "   (child process: Love's kernel + DC-FFT operator + p + u, FFTW_MEASURE)\n";
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
