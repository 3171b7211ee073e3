#include "model/auto_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>

#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/pipeline_error.hpp"
#include "core/detail/brief.hpp"
#include "core/detail/fft_size.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "model/cost_model.hpp"

namespace coatfft {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Love's DC-FFT and direct summation are exact up to rounding: 1e-15 to 1e-14 relative measured
// against each other (tests/test_convolution.cpp); the bound keeps a margin.
constexpr double rounding_error = 1e-13;
// frf-split's operator error per unit of its kernel tolerance: at most 0.05 over the coated
// cases of bench_auto_calibration (docs/auto.md section 1); taken as 0.1.
constexpr double split_error_per_tolerance = 0.1;
// Why a candidate is left out of a distributed choice (AutoRequest::distributed).
constexpr const char* not_distributed = "does not run distributed";

using detail::brief;

struct Context {
  const Grid& grid;
  const Frf& frf;
  bool love = false;  // the body is a homogeneous LayerStack
  AutoRequest request;
  std::ptrdiff_t fft_nx = 0;  // DC-FFT's padded lattice
  std::ptrdiff_t fft_ny = 0;
  int threads = 1;
};

void finish(MethodCandidate& c, const AutoRequest& request) {
  if (request.first_in_process && c.method != Method::direct)
    c.setup_seconds += fftw_start_seconds();
  c.total_seconds = c.setup_seconds + request.applications * c.apply_seconds;
  if (std::isfinite(c.predicted_error) && c.predicted_error > request.tolerance) {
    c.admissible = false;
    c.note =
        detail::concat("predicted error ", c.predicted_error, " > tolerance ", request.tolerance);
  }
}

MethodCandidate love_candidate(const Context& x, Method method) {
  MethodCandidate c{method, rounding_error, 0, 0, 0, x.love, ""};
  if (!x.love) {
    c.predicted_error = kInfinity;
    c.note = "Love's coefficients need a homogeneous body";
    return c;
  }
  const double cells = static_cast<double>(x.grid.nx()) * static_cast<double>(x.grid.ny());
  if (method == Method::direct) {
    c.setup_seconds = predicted_love_setup_seconds(x.grid, 1, 1);
    c.apply_seconds = predicted_direct_apply_seconds(x.grid);
    c.admissible = cells <= static_cast<double>(max_direct_cells);
    c.note = c.admissible ? "exact, O(N^2) per application"
                          : detail::concat("more than ", max_direct_cells, " cells");
  } else {
    c.setup_seconds = predicted_love_setup_seconds(x.grid, x.fft_nx, x.fft_ny);
    c.apply_seconds = predicted_dcfft_apply_seconds(x.fft_nx, x.fft_ny, x.threads);
    c.note = "exact (Liu, Wang & Liu 2000)";
  }
  finish(c, x.request);
  return c;
}

MethodCandidate split_candidate(const Context& x, double split_tolerance) {
  SplitKernelOptions o;
  o.tolerance = split_tolerance;
  o.threads = x.threads;
  MethodCandidate c{Method::frf_split, 0, 0, 0, 0, true, ""};
  if (x.love) {
    // The split kernel of a homogeneous FRF is Love's: dcfft, without the FRF's scan.
    c.predicted_error = rounding_error;
    c.admissible = false;
    c.note = "the same coefficients as dcfft on a homogeneous body";
    return c;
  }
  const SplitKernelWork work = split_frf_kernel_work(x.grid, x.frf, o);
  if (!work.lattice_fits) {
    c.admissible = false;
    c.predicted_error = kInfinity;
    c.note = detail::concat("a short-range lattice of ", work.lattice_entries,
                            " entries: more than the split kernel takes");
    return c;
  }
  c.predicted_error = work.remainder_zero ? rounding_error : predicted_split_error(o.tolerance);
  c.setup_seconds = predicted_split_setup_seconds(x.grid, work, x.threads);
  c.apply_seconds = predicted_dcfft_apply_seconds(x.fft_nx, x.fft_ny, x.threads);
  c.note = detail::concat("split kernel tolerance ", o.tolerance);
  finish(c, x.request);
  return c;
}

// frf-spectral and frf-dcfft at alpha ~ 2 (a larger alpha costs alpha^2 more per application of
// frf-spectral, and more setup of frf-dcfft, for an error falling only like 1/alpha). Their
// error is a periodisation error that only a proxy run predicts
// (convolution/operators/pipeline_error.hpp), so it is evaluated only where the method, prediction
// included, would be the cheapest. lattice_cost: their cost at `alpha`, without the error
// prediction.
MethodCandidate lattice_cost(const Context& x, Method method, double alpha) {
  MethodCandidate c{method, kInfinity, 0, 0, 0, false, ""};
  const auto mx =
      static_cast<std::ptrdiff_t>(std::llround(alpha * static_cast<double>(x.grid.nx())));
  const auto my =
      static_cast<std::ptrdiff_t>(std::llround(alpha * static_cast<double>(x.grid.ny())));
  c.setup_seconds = predicted_lattice_setup_seconds(x.grid, mx, my);
  c.apply_seconds = predicted_dcfft_apply_seconds(mx, my, x.threads);
  c.total_seconds = c.setup_seconds + x.request.applications * c.apply_seconds;
  return c;
}

MethodCandidate lattice_candidate(const Context& x, Method method, double best_total) {
  const double alpha = lattice_alpha(x.grid);
  MethodCandidate c = lattice_cost(x, method, alpha);
  if (x.request.distributed) {
    c.note = not_distributed;
    return c;
  }
  const PipelineErrorProxy proxy = pipeline_error_proxy(x.grid, 2.0);
  const double prediction =
      predicted_split_setup_seconds(proxy.grid, split_frf_kernel_work(proxy.grid, x.frf), 1) +
      3 * predicted_dcfft_apply_seconds(2 * proxy.grid.nx(), 2 * proxy.grid.ny(), 1);
  c.setup_seconds += prediction;
  c.total_seconds += prediction;
  const double start = x.request.first_in_process ? fftw_start_seconds() : 0.0;
  if (c.total_seconds + start >= best_total) {
    c.note = "not evaluated: with the prediction of its error it costs more than the best";
    return c;
  }
  c.predicted_error = predicted_pipeline_error(x.grid, x.frf, method, alpha, x.threads);
  c.admissible = true;
  c.note = detail::concat("alpha = ", brief(alpha), ", g(0) regularized");
  finish(c, x.request);
  return c;
}

void check_request(const AutoRequest& r) {
  COATFFT_REQUIRE(std::isfinite(r.tolerance) && r.tolerance >= 1e-12 && r.tolerance <= 0.1,
                  "tolerance = ", r.tolerance, ": must be in [1e-12, 0.1]");
  COATFFT_REQUIRE(std::isfinite(r.applications) && r.applications >= 1,
                  "applications = ", r.applications, ": must be >= 1");
  COATFFT_REQUIRE(r.max_threads >= 1 && r.max_threads <= max_threads, "threads = ", r.max_threads,
                  ": must be in 1..", max_threads);
}

void size(Context& x) {
  x.fft_nx = DcfftOperator::padded_size(x.grid.nx(), InfluenceKernel::Form::coefficients);
  x.fft_ny = DcfftOperator::padded_size(x.grid.ny(), InfluenceKernel::Form::coefficients);
  const double points = static_cast<double>(x.fft_nx) * static_cast<double>(x.fft_ny);
  x.threads = assumed_speedup(points, x.request.max_threads) > 1 ? x.request.max_threads : 1;
}

MethodCandidate predict(Context x, const OperatorOptions& o) {
  x.request.max_threads = o.threads;
  size(x);
  x.threads = o.threads;
  switch (o.method) {
    case Method::direct:
    case Method::dcfft:
      return love_candidate(x, o.method);
    case Method::frf_split:
      return split_candidate(x, o.split.tolerance);
    default: {
      // The error is not the model's: convolution/operators/pipeline_error.hpp predicts it.
      MethodCandidate c = lattice_cost(x, o.method, o.alpha);
      c.admissible = true;
      finish(c, x.request);
      return c;
    }
  }
}

MethodChoice choose(Context x) {
  check_request(x.request);
  size(x);
  MethodChoice choice;
  choice.candidates = {love_candidate(x, Method::direct), love_candidate(x, Method::dcfft),
                       split_candidate(x, split_tolerance_for(x.request.tolerance))};
  if (x.request.distributed) {
    MethodCandidate& direct = choice.candidates.front();
    direct.admissible = false;
    direct.note = not_distributed;
  }
  const auto best = [&] {
    double t = kInfinity;
    for (const auto& c : choice.candidates)
      if (c.admissible) t = std::min(t, c.total_seconds);
    return t;
  };
  for (const Method m : {Method::frf_spectral, Method::frf_dcfft})
    choice.candidates.push_back(lattice_candidate(x, m, best()));
  const auto chosen = std::min_element(choice.candidates.begin(), choice.candidates.end(),
                                       [](const auto& a, const auto& b) {
                                         return std::make_tuple(!a.admissible, a.total_seconds) <
                                                std::make_tuple(!b.admissible, b.total_seconds);
                                       });
  COATFFT_REQUIRE(chosen->admissible, "no method meets tolerance ", x.request.tolerance);
  choice.chosen = *chosen;
  OperatorOptions& o = choice.options;
  o.method = chosen->method;
  o.threads = x.threads;
  o.planning = x.request.planning;
  o.split.tolerance = split_tolerance_for(x.request.tolerance);
  o.alpha = lattice_alpha(x.grid);
  choice.why = detail::concat(to_string(o.method), ": the cheapest method within ",
                              brief(x.request.tolerance), " (predicted error ",
                              brief(chosen->predicted_error), ", ", brief(chosen->setup_seconds),
                              " s setup + ", brief(x.request.applications), " x ",
                              brief(chosen->apply_seconds), " s); ", chosen->note);
  return choice;
}

}  // namespace

double lattice_alpha(const Grid& grid) {
  if (grid.nx() != grid.ny()) return 2.0;
  const auto n = static_cast<double>(grid.nx());
  return static_cast<double>(detail::fast_fft_size(2 * grid.nx())) / n;
}

double split_tolerance_for(double tolerance) {
  return std::clamp(tolerance, 1e-13, 1e-3);
}

double predicted_split_error(double split_tolerance) {
  return split_error_per_tolerance * split_tolerance;
}

MethodChoice choose_method(const Grid& grid, const LayerStack& body, const AutoRequest& request) {
  const std::unique_ptr<Frf> frf = make_frf(body);
  return choose(Context{grid, *frf, body.is_homogeneous(), request});
}

MethodChoice choose_method(const Grid& grid, const Frf& frf, const AutoRequest& request) {
  return choose(Context{grid, frf, false, request});
}

MethodCandidate predict_method(const Grid& grid, const LayerStack& body,
                               const OperatorOptions& options, double applications,
                               bool first_in_process) {
  const std::unique_ptr<Frf> frf = make_frf(body);
  AutoRequest r;
  r.applications = applications;
  r.first_in_process = first_in_process;
  return predict(Context{grid, *frf, body.is_homogeneous(), r}, options);
}

MethodCandidate predict_method(const Grid& grid, const Frf& frf, const OperatorOptions& options,
                               double applications, bool first_in_process) {
  AutoRequest r;
  r.applications = applications;
  r.first_in_process = first_in_process;
  return predict(Context{grid, frf, false, r}, options);
}

}  // namespace coatfft
