#include "convolution/operators/make_operator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "convolution/kernels/frf_influence_kernel.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "convolution/operators/detail/frf_spectral_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "convolution/operators/pipeline_error.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace coatfft {
namespace {

// `make()` (an influence kernel), its wall time added to the report's kernel_seconds.
template <typename Make>
InfluenceKernel timed_kernel(OperatorReport& report, Make&& make) {
  const auto start = std::chrono::steady_clock::now();
  InfluenceKernel kernel = make();
  report.kernel_seconds += detail::seconds_since(start);
  return kernel;
}

// g(0) on the alpha-extended lattice of the FRF pipelines (docs/theory.md section 3).
G0Result pipeline_g0(const Grid& grid, const Frf& frf, const OperatorOptions& o) {
  const double min_alpha = o.method == Method::frf_dcfft ? 2.0 : 1.0;
  return lattice_g0(grid, frf, o.alpha, min_alpha, o.g0, o.g0_tolerance, "make_operator");
}

// The operator of an FRF method; `report` is filled with what was chosen.
std::unique_ptr<SurfaceOperator> frf_operator(const Grid& grid, const Frf& frf,
                                              const OperatorOptions& o, OperatorReport& report) {
  report.frf = frf.name();
  switch (o.method) {
    case Method::frf_spectral: {
      auto op = std::make_unique<FrfSpectralOperator>(grid, frf, o.alpha, pipeline_g0(grid, frf, o),
                                                      o.planning, o.threads);
      report.alpha = o.alpha;
      report.g0 = op->g0();
      report.fft_nx = op->extended_nx();
      report.fft_ny = op->extended_ny();
      // Predicted once the operator is built, so that an FRF the pipeline cannot use has been
      // refused with the pipeline's own message (docs/theory.md 4.6).
      report.predicted_error = predicted_pipeline_error(grid, frf, o.method, o.alpha, o.threads);
      return op;
    }
    case Method::frf_dcfft: {
      const G0Result g0 = pipeline_g0(grid, frf, o);
      report.alpha = o.alpha;
      report.g0 = g0;
      const InfluenceKernel kernel =
          timed_kernel(report, [&] { return frf_dcfft_kernel(grid, frf, o.alpha, g0, o.threads); });
      auto op = std::make_unique<DcfftOperator>(kernel, o.planning, o.threads);
      report.predicted_error = predicted_pipeline_error(grid, frf, o.method, o.alpha, o.threads);
      return op;
    }
    case Method::frf_split: {
      // The split kernel needs no g(0): the singular part of H is taken in closed form in space.
      SplitKernelOptions split = o.split;
      split.threads = o.threads;
      SplitKernelReport split_report;
      const InfluenceKernel kernel =
          timed_kernel(report, [&] { return split_frf_kernel(grid, frf, split, &split_report); });
      report.split = split_report;
      return std::make_unique<DcfftOperator>(kernel, o.planning, o.threads);
    }
    case Method::direct:
    case Method::dcfft:
      break;
  }
  throw InvalidArgument(detail::concat(
      "make_operator: method \"", to_string(o.method),
      "\" uses Love's coefficients of a homogeneous half-space, which an FRF alone does not give; "
      "use \"frf-split\", \"frf-dcfft\" or \"frf-spectral\""));
}

// Boundary::periodic: the periodic coefficients of the body's FRF (exact for the periodic
// problem, for dcfft and frf-split alike) and their circular convolution on the grid itself.
std::unique_ptr<SurfaceOperator> periodic_operator(const Grid& grid, const Frf& frf,
                                                   const OperatorOptions& o,
                                                   OperatorReport& report) {
  report.frf = frf.name();
  PeriodicKernelOptions kernel;
  kernel.threads = o.threads;
  const auto start = std::chrono::steady_clock::now();
  const Field coefficients = periodic_influence_kernel(grid, frf, kernel);
  report.kernel_seconds += detail::seconds_since(start);
  report.fft_nx = grid.nx();
  report.fft_ny = grid.ny();
  return std::make_unique<PeriodicOperator>(grid, coefficients, o.method, o.planning,
                                            Precision::double_precision, o.threads);
}

std::unique_ptr<SurfaceOperator> kernel_operator(const InfluenceKernel& kernel,
                                                 const OperatorOptions& o) {
  if (o.method == Method::direct) return std::make_unique<DirectOperator>(kernel);
  return std::make_unique<DcfftOperator>(kernel, o.planning, o.threads);
}

// Times `build` and completes the report's common fields.
template <typename Build>
BuiltOperator timed(const Grid& grid, const OperatorOptions& options, Build&& build) {
  check_operator_options(grid, options);
  const auto start = std::chrono::steady_clock::now();
  BuiltOperator built;
  built.op = build(built.report);
  // DC-FFT's padded lattice, whichever method built it (frf-spectral sets its own in `build`).
  if (const auto* dc = dynamic_cast<const DcfftOperator*>(built.op.get())) {
    built.report.fft_nx = dc->padded_nx();
    built.report.fft_ny = dc->padded_ny();
  }
  built.report.method = built.op->method();
  if (built.report.method == Method::direct) built.report.fft_nx = built.report.fft_ny = 0;
  built.report.setup_seconds = detail::seconds_since(start);
  return built;
}

}  // namespace

Method exact_method(const LayerStack& body) {
  return body.is_homogeneous() ? Method::dcfft : Method::frf_split;
}

// Love's coefficients exist in closed form only for the homogeneous half-space.
void check_love_body(const LayerStack& body, Method method) {
  COATFFT_REQUIRE(!uses_love_coefficients(method) || body.is_homogeneous(), "method \"",
                  to_string(method),
                  "\" uses Love's coefficients of a homogeneous half-space; for a coated body "
                  "use \"frf-split\", \"frf-dcfft\" or \"frf-spectral\"");
}

void check_operator_options(const Grid& grid, const OperatorOptions& o) {
  COATFFT_REQUIRE(o.threads >= 1 && o.threads <= max_threads, "threads = ", o.threads,
                  " must be in 1..", max_threads);
  COATFFT_REQUIRE(o.g0_tolerance > 0 && o.g0_tolerance < 1, "g(0) tolerance = ", o.g0_tolerance,
                  " must be in (0, 1)");
  COATFFT_REQUIRE(std::isfinite(o.alpha) && o.alpha >= 1, "alpha = ", o.alpha, " must be >= 1");
  COATFFT_REQUIRE(o.method != Method::direct || grid.nb_cells() <= max_direct_cells,
                  "direct summation on ", grid.nx(), " x ", grid.ny(), " cells: it is limited to ",
                  max_direct_cells,
                  " cells (its cost grows as (nx ny)^2); use \"dcfft\", which "
                  "gives the same result");
  COATFFT_REQUIRE(
      o.boundary == Boundary::free || o.method == Method::dcfft || o.method == Method::frf_split,
      "method \"", to_string(o.method),
      "\" computes free (non-periodic) surfaces: on a periodic boundary use "
      "\"frf-split\" (any body) or \"dcfft\" (homogeneous)");
  if (!samples_frf_lattice(o.method)) return;
  for (const auto n : {grid.nx(), grid.ny()}) {
    const double m = o.alpha * static_cast<double>(n);
    COATFFT_REQUIRE(std::abs(m - std::round(m)) < 1e-9 * m, "alpha = ", o.alpha,
                    ": alpha * nx and alpha * ny must be whole numbers of cells (alpha * ", n,
                    " = ", m, ")");
  }
  // Offsets up to N - 1 must not wrap onto each other on the extended lattice.
  COATFFT_REQUIRE(o.method != Method::frf_dcfft || o.alpha >= 2, "alpha = ", o.alpha,
                  ": frf-dcfft needs alpha >= 2");
}

BuiltOperator make_operator(const Grid& grid, const LayerStack& body,
                            const OperatorOptions& options) {
  return timed(grid, options, [&](OperatorReport& report) -> std::unique_ptr<SurfaceOperator> {
    if (options.boundary == Boundary::periodic)
      return periodic_operator(grid, *make_frf(body), options, report);
    if (!uses_love_coefficients(options.method))
      return frf_operator(grid, *make_frf(body), options, report);
    check_love_body(body, options.method);
    const InfluenceKernel kernel = timed_kernel(report, [&] {
      return love_kernel(grid, body.substrate().plane_strain_modulus(), options.threads);
    });
    return kernel_operator(kernel, options);
  });
}

BuiltOperator make_operator(const Grid& grid, const Frf& frf, const OperatorOptions& options) {
  return timed(grid, options, [&](OperatorReport& report) {
    return options.boundary == Boundary::periodic ? periodic_operator(grid, frf, options, report)
                                                  : frf_operator(grid, frf, options, report);
  });
}

BuiltOperator make_operator(const InfluenceKernel& kernel, const OperatorOptions& options) {
  return timed(kernel.grid(), options,
               [&](OperatorReport&) { return kernel_operator(kernel, options); });
}

BuiltTangentialOperator make_tangential_operator(const Grid& grid, const LayerStack& body,
                                                 const TangentialOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TractionKernelOptions kernel = options.kernel;
  kernel.lattice.threads = options.threads;
  BuiltTangentialOperator built;
  if (options.boundary == Boundary::periodic) {
    PeriodicKernelOptions periodic;
    periodic.tolerance = std::min(kernel.tolerance, 1e-6);
    periodic.max_evaluations = kernel.lattice.max_evaluations;
    periodic.threads = options.threads;
    built.op = std::make_unique<CerrutiOperator>(grid, body, periodic, options.planning);
  } else {
    built.op =
        std::make_unique<CerrutiOperator>(grid, body, kernel, options.planning, &built.report);
  }
  built.setup_seconds = detail::seconds_since(start);
  return built;
}

}  // namespace coatfft
