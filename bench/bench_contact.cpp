// Contact solver cost on the Hertz problem (DC-FFT operator): Polonsky-Keer iterations to a
// relative pressure change of 1e-10 at N = 256 ... 2048, classic and preconditioned, with the
// displacement moved by linearity (one application per iteration) and recomputed at every
// iteration (the original form), under load and approach control, and the wall time of a solve
// as a multiple of one operator application timed in the same run. Prints `# key = value` headers
// and CSV rows, and writes the same to bench/results/contact.csv (or OUTPUT).
//   bench_contact [OUTPUT] [--planning estimate|measure] [--sizes N ...]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

constexpr double kModulus = 1e11;   // E* [Pa]
constexpr double kRadius = 0.01;    // R [m]
constexpr double kLoad = 10.0;      // W [N]
constexpr double kHalfWidth = 1.5;  // domain [-1.5 a, 1.5 a]^2, as in contact_table

double ms_since(Clock::time_point start) {
  return 1e3 * detail::seconds_since(start);
}

// Counts and times the applications made inside a solve, so that the solve's cost can be expressed
// in applications measured under the same machine load (this machine is shared).
class TimedOperator final : public SurfaceOperator {
 public:
  explicit TimedOperator(SurfaceOperator& inner) : inner_(inner) {}
  const Grid& grid() const override { return inner_.grid(); }
  void apply(const Field& p, Field& u) override {
    const auto start = Clock::now();
    inner_.apply(p, u);
    ms_ += ms_since(start);
    ++count_;
  }
  Method method() const override { return inner_.method(); }
  using SurfaceOperator::apply;
  int count() const { return count_; }
  double ms() const { return ms_; }

 private:
  SurfaceOperator& inner_;
  int count_ = 0;
  double ms_ = 0.0;
};

struct Row {
  std::ptrdiff_t n;
  std::string control;
  bool preconditioned;
  bool update_by_linearity;
  int iterations;
  double residual;
  bool converged;
  double plan_ms;
  double apply_ms_min;
  double apply_ms_median;
  double solve_ms;
  int applies;         // operator applications inside the solve
  double in_solve_ms;  // their total time
  double radius_error;
  double pressure_error;
  double load_or_approach_error;
};

Row run(std::ptrdiff_t n, ContactControl control, bool preconditioned, bool update_by_linearity,
        Planning planning) {
  const HertzSphere ref = hertz_sphere_for_load(kLoad, kRadius, kModulus);
  const double width = 2 * kHalfWidth * ref.contact_radius;
  const Grid grid(n, n, width, width);
  OperatorOptions options;
  options.planning = planning;
  const BuiltOperator built = make_operator(love_kernel(grid, kModulus), options);
  SurfaceOperator& op = *built.op;
  const double plan_ms = 1e3 * built.report.setup_seconds;
  const Field h = height(grid, Sphere{kRadius});
  // One application, timed on a Hertz-like pressure (the cost does not depend on the values).
  Field p(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      p(i, j) = ref.pressure(std::hypot(grid.x(i), grid.y(j)));
    }
  }
  Field u;
  op.apply(p, u);  // warm-up
  std::vector<double> times;
  const int repeats = n <= 256 ? 20 : 7;
  for (int k = 0; k < repeats; ++k) {
    const auto start = Clock::now();
    op.apply(p, u);
    times.push_back(ms_since(start));
  }
  ContactOptions opts;
  opts.compute_approach = true;
  opts.preconditioned = preconditioned;
  opts.update_by_linearity = update_by_linearity;
  TimedOperator timed(op);
  ContactSolver solver(timed, opts);  // plans the preconditioner: outside the timed solve
  const auto start = Clock::now();
  const ContactResult res = control == ContactControl::load
                                ? solver.solve_load(h, kLoad)
                                : solver.solve_approach(h, ref.approach);
  const double solve_ms = ms_since(start);
  if (res.operator_applications != timed.count()) {
    throw std::runtime_error(detail::concat("the solver reported ", res.operator_applications,
                                            " applications, but made ", timed.count()));
  }
  const double third_error = control == ContactControl::load
                                 ? res.approach.value_or(0.0) / ref.approach - 1
                                 : res.load / ref.load - 1;
  return {n,
          control == ContactControl::load ? "load" : "approach",
          preconditioned,
          update_by_linearity,
          res.iterations,
          res.residual,
          res.converged && !res.touches_boundary,
          plan_ms,
          *std::min_element(times.begin(), times.end()),
          detail::median(times),
          solve_ms,
          res.operator_applications,
          timed.ms(),
          res.contact_radius.value_or(0.0) / ref.contact_radius - 1,
          res.max_pressure / ref.max_pressure - 1,
          third_error};
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Contact solver cost on the Hertz problem (DC-FFT)"};
  std::string path = "bench/results/contact.csv";
  app.add("output", path, "CSV file").show_default();
  std::string planning_name = "estimate";
  app.add("--planning", planning_name, "FFTW planner effort: estimate or measure").show_default();
  std::vector<std::ptrdiff_t> sizes = {256, 512, 1024, 2048};
  app.add("--sizes", sizes, "grid sizes N (N x N cells)").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    const Planning planning = parse_planning(planning_name);
    std::ostringstream out;
    out << "# benchmark = bench_contact (Polonsky-Keer on DC-FFT, Hertz sphere)\n";
    coatfft::bench::write_machine_header(out);
    out << "# fftw_flags = " << (planning == Planning::measure ? "FFTW_MEASURE" : "FFTW_ESTIMATE")
        << "\n"
        << "# fftw_threads = 1\n"
        << "# problem = R " << kRadius << " m, E* " << kModulus << " Pa, W " << kLoad
        << " N, domain [-" << kHalfWidth << " a, " << kHalfWidth << " a]^2, exact sphere\n"
        << "# tolerance = 1e-10 (relative pressure change per iteration)\n"
        << "# variants: linearity = 1 moves u by linearity and recomputes it now and then (about\n"
        << "#   one application per iteration); 0 recomputes u = K p at every iteration (Polonsky "
           "&\n"
        << "#   Keer's original, 2 per iteration: the solver before); preconditioned = 1 adds one\n"
        << "#   periodic N x N FFT pair per iteration (the |k| multiplier); the unpreconditioned\n"
        << "#   iteration runs up to N = 512 only\n"
        << "# columns: apply_ms_* = one application timed alone (warm, repeated); applies and\n"
        << "#   in_solve_apply_ms = count and mean time of the applications inside the solve;\n"
        << "#   solve_over_apply = solve_ms / in_solve_apply_ms (robust to machine load, which\n"
        << "#   slows both alike); errors are relative to Hertz (a from sqrt(A/pi)); third_error "
           "is the\n"
        << "#   approach error under load control and the load error under approach control\n"
        << "control,preconditioned,linearity,N,iterations,residual,converged,plan_ms,apply_ms_min,"
           "apply_ms_median,solve_ms,applies,in_solve_apply_ms,solve_over_apply,a_error,p0_error,"
           "third_error\n";
    std::cout << out.str() << std::flush;
    for (const std::ptrdiff_t n : sizes) {
      for (const ContactControl control : {ContactControl::load, ContactControl::approach}) {
        for (const bool preconditioned : {true, false}) {
          if (!preconditioned && n > 512) continue;  // hundreds of iterations: minutes each
          for (const bool linearity : {true, false}) {
            const Row r = run(n, control, preconditioned, linearity, planning);
            std::ostringstream row;
            row.precision(4);
            row << r.control << "," << (r.preconditioned ? 1 : 0) << ","
                << (r.update_by_linearity ? 1 : 0) << "," << r.n << "," << r.iterations << ","
                << r.residual << "," << (r.converged ? 1 : 0) << "," << r.plan_ms << ","
                << r.apply_ms_min << "," << r.apply_ms_median << "," << r.solve_ms << ","
                << r.applies << "," << r.in_solve_ms / r.applies << ","
                << r.solve_ms / (r.in_solve_ms / r.applies) << "," << r.radius_error << ","
                << r.pressure_error << "," << r.load_or_approach_error << "\n";
            std::cout << row.str() << std::flush;
            out << row.str();
          }
        }
      }
    }
    coatfft::bench::write_text_file(path, out.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_contact: " << e.what() << "\n";
    return 1;
  }
}
