// The distributed periodic operator (distributed/distributed_periodic_operator.hpp) on one grid:
// its setup, one application (median of repeats, each timed from a barrier to the slowest rank),
// the share of an application spent in the transforms' transposes (the communication, with the
// wait for the slowest rank), and the peak resident memory of every rank, before the operator
// (MPI and the library) and after. With --serial, the same for the serial PeriodicOperator in a
// process without MPI. One CSV row on stdout (rank 0); scripts/distributed_scale_run.sh runs the
// matrix of sizes and rank counts and writes bench/results/distributed_operator.csv.
//   mpirun -np P bench_distributed --size N [--repeats R] [--threads T]
//   bench_distributed --serial --size N
// Body: TiN 5 um on steel, period 1 mm; pressure uniform random in [0, 1 GPa].
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "distributed/distributed_periodic_operator.hpp"
#include "distributed/mpi_session.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

struct Options {
  std::ptrdiff_t n = 1024;
  int repeats = 5;
  int threads = 1;
  bool serial = false;
};

// Rows y0 <= j < y0 + rows of a random pressure field (each row from its own generator: the same
// field at any rank count).
Field random_rows(std::ptrdiff_t nx, std::ptrdiff_t y0, std::ptrdiff_t rows) {
  Field p(nx, rows);
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(y0 + r));
    for (std::ptrdiff_t i = 0; i < nx; ++i)
      p(i, r) = 1e9 * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  }
  return p;
}

struct Row {
  double setup_s = 0, apply_ms = 0, transpose_ms = 0, rss_before_mb = 0, rss_max_mb = 0,
         rss_sum_mb = 0;
};

// The median over repeats of f's time on the slowest rank [ms] (`sync` a barrier, or nothing).
template <typename F, typename Sync, typename Max>
double median_ms(int repeats, F&& f, Sync&& sync, Max&& max) {
  f();  // warm-up
  std::vector<double> times;
  for (int k = 0; k < repeats; ++k) {
    sync();
    const auto start = Clock::now();
    f();
    times.push_back(max(1e3 * detail::seconds_since(start)));
  }
  return detail::median(times);
}

Row run_distributed(const Options& o, const Frf& frf, const Grid& grid) {
  const Communicator comm = Communicator::world();
  Row row;
  row.rss_before_mb = comm.max(bench::peak_rss_mb());
  comm.barrier();
  const auto start = Clock::now();
  DistributedPeriodicOperator op(comm, grid, frf, {.threads = o.threads}, Planning::estimate,
                                 o.threads);
  row.setup_s = comm.max(detail::seconds_since(start));
  const Field p = random_rows(grid.nx(), op.slab().y0, op.slab().rows);
  Field u;
  const double before = op.communication_seconds();
  row.apply_ms = median_ms(
      o.repeats, [&] { op.apply(p, u); }, [&] { comm.barrier(); },
      [&](double t) { return comm.max(t); });
  row.transpose_ms = comm.max(1e3 * (op.communication_seconds() - before) / (o.repeats + 1));
  row.rss_max_mb = comm.max(bench::peak_rss_mb());
  row.rss_sum_mb = comm.sum(bench::peak_rss_mb());
  return row;
}

Row run_serial(const Options& o, const Frf& frf, const Grid& grid) {
  Row row;
  row.rss_before_mb = bench::peak_rss_mb();
  const auto start = Clock::now();
  PeriodicOperator op(grid, periodic_influence_kernel(grid, frf, {.threads = o.threads}),
                      Method::frf_spectral, Planning::estimate, Precision::double_precision,
                      o.threads);
  row.setup_s = detail::seconds_since(start);
  const Field p = random_rows(grid.nx(), 0, grid.ny());
  Field u;
  row.apply_ms = median_ms(
      o.repeats, [&] { op.apply(p, u); }, [] {}, [](double t) { return t; });
  row.rss_max_mb = row.rss_sum_mb = bench::peak_rss_mb();
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"The distributed periodic operator on one grid (one CSV row)"};
  Options o;
  app.add("--size", o.n, "grid size N (N x N cells)").show_default();
  app.add("--repeats", o.repeats, "timed applications").show_default();
  app.add("--threads", o.threads, "FFTW threads per rank").show_default();
  app.flag("--serial", o.serial, "the serial PeriodicOperator, without MPI");
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    const LayerStack body({Coating{Material(400e9, 0.25), 5e-6, Interface::bonded}},
                          Material(210e9, 0.3));
    const auto frf = make_frf(body);
    const Grid grid(o.n, o.n, 1e-3, 1e-3);
    std::unique_ptr<MpiSession> session;
    int ranks = 0, rank = 0;
    Row row;
    if (o.serial) {
      row = run_serial(o, *frf, grid);
    } else {
      session = std::make_unique<MpiSession>(argc, argv);
      ranks = session->world().size();
      rank = session->world().rank();
      row = run_distributed(o, *frf, grid);
    }
    if (rank == 0)
      std::printf("%td,%s,%d,%.3f,%.2f,%.2f,%.3f,%.0f,%.0f,%.0f\n", o.n,
                  o.serial ? "serial" : std::to_string(ranks).c_str(), o.threads, row.setup_s,
                  row.apply_ms, row.transpose_ms,
                  row.apply_ms > 0 ? row.transpose_ms / row.apply_ms : 0.0, row.rss_before_mb,
                  row.rss_max_mb, row.rss_sum_mb);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_distributed: " << e.what() << "\n";
    return 1;
  }
}
