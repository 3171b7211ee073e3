#include "distributed/make_distributed_operator.hpp"

#include <chrono>

#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "distributed/distributed_dcfft_operator.hpp"
#include "distributed/distributed_periodic_operator.hpp"

namespace coatfft {

namespace {

using Clock = std::chrono::steady_clock;

void require_distributed(const OperatorOptions& o, bool love) {
  COATFFT_REQUIRE(runs_distributed(o.method), "method \"", to_string(o.method),
                  "\" does not run distributed (there \"dcfft\" or \"frf-split\")");
  COATFFT_REQUIRE(love || o.boundary == Boundary::periodic || o.method == Method::frf_split,
                  "method \"dcfft\" uses Love's coefficients of a homogeneous half-space: a body "
                  "given by its FRF takes \"frf-split\"");
}

// The operator of `frf` (periodic, or frf-split's on a free boundary), as make_operator's.
std::unique_ptr<DistributedOperator> distributed_frf_operator(const Communicator& comm,
                                                              const Grid& grid, const Frf& frf,
                                                              const OperatorOptions& o,
                                                              OperatorReport& report) {
  report.frf = frf.name();
  if (o.boundary == Boundary::periodic) {
    PeriodicKernelOptions kernel;
    kernel.threads = o.threads;
    return std::make_unique<DistributedPeriodicOperator>(comm, grid, frf, kernel, o.planning,
                                                         o.threads, o.method);
  }
  SplitKernelOptions split = o.split;
  split.threads = o.threads;
  SplitKernelReport split_report;
  auto op = std::make_unique<DistributedDcfftOperator>(comm, grid, frf, split, o.planning,
                                                       o.threads, &split_report);
  report.split = split_report;
  return op;
}

// The report's lattice and time, once the operator is built.
BuiltDistributedOperator built_distributed(std::unique_ptr<DistributedOperator> op,
                                           OperatorReport report, const Grid& grid,
                                           Clock::time_point start) {
  const bool periodic = op->periodic();
  report.method = op->method();
  report.fft_nx = periodic ? grid.nx() : 2 * grid.nx();
  report.fft_ny = periodic ? grid.ny() : 2 * grid.ny();
  report.setup_seconds = detail::seconds_since(start);
  return {std::move(op), std::move(report)};
}

}  // namespace

bool runs_distributed(Method method) {
  return method == Method::dcfft || method == Method::frf_split;
}

BuiltDistributedOperator make_distributed_operator(const Communicator& comm, const Grid& grid,
                                                   const LayerStack& body,
                                                   const OperatorOptions& options) {
  const auto start = Clock::now();
  check_operator_options(grid, options);
  require_distributed(options, true);
  OperatorReport report;
  if (options.boundary == Boundary::free && options.method == Method::dcfft) {
    check_love_body(body, options.method);
    auto op = std::make_unique<DistributedDcfftOperator>(
        comm, grid, body.substrate().plane_strain_modulus(), options.planning, options.threads);
    return built_distributed(std::move(op), std::move(report), grid, start);
  }
  auto op = distributed_frf_operator(comm, grid, *make_frf(body), options, report);
  return built_distributed(std::move(op), std::move(report), grid, start);
}

BuiltDistributedOperator make_distributed_operator(const Communicator& comm, const Grid& grid,
                                                   const Frf& frf, const OperatorOptions& options) {
  const auto start = Clock::now();
  check_operator_options(grid, options);
  require_distributed(options, false);
  OperatorReport report;
  auto op = distributed_frf_operator(comm, grid, frf, options, report);
  return built_distributed(std::move(op), std::move(report), grid, start);
}

}  // namespace coatfft
