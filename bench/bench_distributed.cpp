// The distributed periodic operator (distributed/distributed_periodic_operator.hpp) on one grid:
// its setup, one application (median of repeats, each timed from a barrier to the slowest rank),
// the share of an application spent in the transforms' transposes (the communication, with the
// wait for the slowest rank), and the peak resident memory of every rank, before the operator
// (MPI and the library) and after. With --serial, the same for the serial PeriodicOperator in a
// process without MPI. One CSV row on stdout (rank 0); scripts/distributed_scale_run.sh runs the
// matrix of sizes and rank counts and writes bench/results/distributed_operator.csv.
//   mpirun -np P bench_distributed --size N [--repeats R] [--threads T]
//   bench_distributed --serial --size N
// With --contact, a periodic rough contact instead (one CSV row: setup, iterations, applications,
// solve time, the transposes' share of it, peak memory): the surface of scripts/rough_scale_run.sh
// (H 0.8, rms slope 0.05, shortest wavelength 16 cells, roll-off 0.25 mm, seed 2004) made by the
// ranks, pressed by a flat to a mean pressure of 0.045 E* times the rms slope (about 10 % contact),
// tolerance 1e-10, no nested start in either unless --nested (then both start nested; the row
// ends with the coarse grids' applications); written by scripts/distributed_scale_run.sh to
// bench/results/distributed_contact.csv.
// With --free, the free surface's DC-FFT instead of the periodic operator: DistributedDcfftOperator
// against the serial DcfftOperator with Love's coefficients, on steel (written by
// scripts/distributed_scale_run.sh to bench/results/distributed_dcfft.csv). With --free-split, the
// free surface of the coated body by frf-split: DistributedDcfftOperator with the split kernel's
// coefficients (its lattice transformed over the ranks) against DcfftOperator(split_frf_kernel)
// (bench/results/distributed_split.csv); its setup is the kernel's.
// Body: TiN 5 um on steel, period 1 mm (--free: steel); pressure uniform random in [0, 1 GPa].
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "bench/slowest_rank_median.hpp"
#include "contact/contact_solver.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/detail/timing.hpp"
#include "distributed/distributed_contact.hpp"
#include "distributed/distributed_dcfft_operator.hpp"
#include "distributed/distributed_periodic_operator.hpp"
#include "distributed/mpi_session.hpp"
#include "distributed/self_affine_slab.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace {

using namespace coatfft;
using Clock = std::chrono::steady_clock;

struct Options {
  std::ptrdiff_t n = 1024;
  int repeats = 5;
  int threads = 1;
  bool serial = false;
  bool contact = false;
  bool nested = false;      // the contact's nested start, serial and distributed alike
  bool free = false;        // DC-FFT of the free surface on steel
  bool free_split = false;  // the free surface of the coated body by frf-split
};

const Material steel(210e9, 0.3);

// The operator measured: the periodic one of the coated body, or DC-FFT on steel (--free).
std::unique_ptr<DistributedOperator> distributed_operator(const Options& o,
                                                          const Communicator& comm, const Frf& frf,
                                                          const Grid& grid) {
  if (o.free)
    return std::make_unique<DistributedDcfftOperator>(comm, grid, steel.plane_strain_modulus(),
                                                      Planning::estimate, o.threads);
  if (o.free_split)
    return std::make_unique<DistributedDcfftOperator>(
        comm, grid, frf, SplitKernelOptions{.threads = o.threads}, Planning::estimate, o.threads);
  return std::make_unique<DistributedPeriodicOperator>(
      comm, grid, frf, PeriodicKernelOptions{.threads = o.threads}, Planning::estimate, o.threads);
}

std::unique_ptr<SurfaceOperator> serial_operator(const Options& o, const Frf& frf,
                                                 const Grid& grid) {
  if (o.free)
    return std::make_unique<DcfftOperator>(
        love_kernel(grid, steel.plane_strain_modulus(), o.threads), Planning::estimate, o.threads);
  if (o.free_split)
    return std::make_unique<DcfftOperator>(
        split_frf_kernel(grid, frf, SplitKernelOptions{.threads = o.threads}), Planning::estimate,
        o.threads);
  return std::make_unique<PeriodicOperator>(
      grid, periodic_influence_kernel(grid, frf, {.threads = o.threads}), Method::frf_spectral,
      Planning::estimate, Precision::double_precision, o.threads);
}

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

Row run_distributed(const Options& o, const Frf& frf, const Grid& grid) {
  const Communicator comm = Communicator::world();
  Row row;
  row.rss_before_mb = comm.max(bench::peak_rss_mb());
  comm.barrier();
  const auto start = Clock::now();
  const std::unique_ptr<DistributedOperator> op = distributed_operator(o, comm, frf, grid);
  row.setup_s = comm.max(detail::seconds_since(start));
  const Field p = random_rows(grid.nx(), op->slab().y0, op->slab().rows);
  Field u;
  const double before = op->communication_seconds();
  row.apply_ms = bench::slowest_rank_median_ms(
      o.repeats, [&] { op->apply(p, u); }, [&] { comm.barrier(); },
      [&](double t) { return comm.max(t); });
  row.transpose_ms = comm.max(1e3 * (op->communication_seconds() - before) / (o.repeats + 1));
  row.rss_max_mb = comm.max(bench::peak_rss_mb());
  row.rss_sum_mb = comm.sum(bench::peak_rss_mb());
  return row;
}

Row run_serial(const Options& o, const Frf& frf, const Grid& grid) {
  Row row;
  row.rss_before_mb = bench::peak_rss_mb();
  const auto start = Clock::now();
  const std::unique_ptr<SurfaceOperator> op = serial_operator(o, frf, grid);
  row.setup_s = detail::seconds_since(start);
  const Field p = random_rows(grid.nx(), 0, grid.ny());
  Field u;
  row.apply_ms = bench::slowest_rank_median_ms(
      o.repeats, [&] { op->apply(p, u); }, [] {}, [](double t) { return t; });
  row.rss_max_mb = row.rss_sum_mb = bench::peak_rss_mb();
  return row;
}

struct ContactRow {
  double setup_s = 0, solve_s = 0, transpose_s = 0, area = 0, rss_max_mb = 0, rss_sum_mb = 0;
  int iterations = 0, applications = 0, coarse_applications = 0;
  bool converged = false;
};

SelfAffineSpec rough_spec(const Grid& grid) {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_slope = 0.05;
  spec.short_cutoff = 16 * grid.dx();
  spec.long_cutoff = 2.5e-4;
  spec.seed = 2004;
  return spec;
}

ContactOptions rough_options(const Options& o) {
  ContactOptions options;
  options.nested_start = o.nested;
  options.threads = o.threads;
  return options;
}

double rough_load(const Grid& grid) {
  return 0.045 * steel.plane_strain_modulus() * 0.05 * grid.lx() * grid.ly();
}

void fill(ContactRow& row, const ContactResult& r, const Grid& grid) {
  row.iterations = r.iterations;
  row.applications = r.operator_applications;
  row.coarse_applications = r.coarse_applications;
  row.converged = r.converged;
  row.area = r.contact_area / (grid.lx() * grid.ly());
}

ContactRow contact_distributed(const Options& o, const Frf& frf, const Grid& grid) {
  const Communicator comm = Communicator::world();
  ContactRow row;
  comm.barrier();
  auto start = Clock::now();
  DistributedPeriodicOperator op(comm, grid, frf, {.threads = o.threads}, Planning::estimate,
                                 o.threads);
  row.setup_s = comm.max(detail::seconds_since(start));
  const Field z = self_affine_slab(comm, grid, rough_spec(grid));
  const Field h = comm.max(z.size() ? z.maxCoeff() : -1e300) - z;
  const auto solver = distributed_contact_solver(op, rough_options(o));
  const double before = op.communication_seconds();
  comm.barrier();
  start = Clock::now();
  const ContactResult r = solver->solve_load(h, rough_load(grid));
  row.solve_s = comm.max(detail::seconds_since(start));
  row.transpose_s = comm.max(op.communication_seconds() - before);
  fill(row, r, grid);
  row.rss_max_mb = comm.max(bench::peak_rss_mb());
  row.rss_sum_mb = comm.sum(bench::peak_rss_mb());
  return row;
}

ContactRow contact_serial(const Options& o, const Frf& frf, const Grid& grid) {
  ContactRow row;
  auto start = Clock::now();
  PeriodicOperator op(grid, periodic_influence_kernel(grid, frf, {.threads = o.threads}),
                      Method::frf_split, Planning::estimate, Precision::double_precision,
                      o.threads);
  row.setup_s = detail::seconds_since(start);
  const Field z = self_affine_surface(grid, rough_spec(grid));
  const Field h = z.maxCoeff() - z;
  ContactSolver solver(op, rough_options(o));
  start = Clock::now();
  const ContactResult r = solver.solve_load(h, rough_load(grid));
  row.solve_s = detail::seconds_since(start);
  fill(row, r, grid);
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
  app.flag("--contact", o.contact, "a periodic rough contact instead of applications");
  app.flag("--nested", o.nested, "--contact with the nested start (serial and distributed)");
  app.flag("--free", o.free, "the free surface's DC-FFT on steel instead of the periodic operator");
  app.flag("--free-split", o.free_split,
           "the free surface of the coated body by frf-split instead of the periodic operator");
  if (const auto status = app.parse(argc, argv)) return *status;
  if ((o.free || o.free_split) && o.contact) {
    std::cerr << "bench_distributed: --free and --free-split measure the operator alone; the "
                 "contact is periodic\n";
    return 2;
  }
  if (o.free && o.free_split) {
    std::cerr << "bench_distributed: --free or --free-split, not both\n";
    return 2;
  }
  try {
    const LayerStack body({Coating{Material(400e9, 0.25), 5e-6, Interface::bonded}}, steel);
    const auto frf = make_frf(body);
    const Grid grid(o.n, o.n, 1e-3, 1e-3);
    std::unique_ptr<MpiSession> session;
    int ranks = 0, rank = 0;
    if (!o.serial) {
      session = std::make_unique<MpiSession>(argc, argv);
      ranks = session->world().size();
      rank = session->world().rank();
    }
    const std::string who = o.serial ? "serial" : std::to_string(ranks);
    if (o.contact) {
      const ContactRow c =
          o.serial ? contact_serial(o, *frf, grid) : contact_distributed(o, *frf, grid);
      if (rank == 0) {
        std::printf("%td,%s,%d,%.3f,%d,%d,%s,%.4f,%.2f,%.2f,%.3f,%.0f,%.0f", o.n, who.c_str(),
                    o.threads, c.setup_s, c.iterations, c.applications,
                    c.converged ? "true" : "false", c.area, c.solve_s, c.transpose_s,
                    c.solve_s > 0 ? c.transpose_s / c.solve_s : 0.0, c.rss_max_mb, c.rss_sum_mb);
        if (o.nested) std::printf(",%d", c.coarse_applications);
        std::printf("\n");
      }
      return 0;
    }
    const Row row = o.serial ? run_serial(o, *frf, grid) : run_distributed(o, *frf, grid);
    if (rank == 0)
      std::printf("%td,%s,%d,%.3f,%.2f,%.2f,%.3f,%.0f,%.0f,%.0f\n", o.n, who.c_str(), o.threads,
                  row.setup_s, row.apply_ms, row.transpose_ms,
                  row.apply_ms > 0 ? row.transpose_ms / row.apply_ms : 0.0, row.rss_before_mb,
                  row.rss_max_mb, row.rss_sum_mb);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_distributed: " << e.what() << "\n";
    return 1;
  }
}
