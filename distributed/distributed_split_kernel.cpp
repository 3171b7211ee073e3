#include "distributed/detail/distributed_split_kernel.hpp"

#include <fftw3-mpi.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdint>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/split_kernel/detail/split_plan.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "distributed/detail/slab_fft.hpp"

namespace coatfft::detail {
namespace {

// Rows [first, first + count) of an array, as one rank holds them.
struct RowBlock {
  std::int64_t first = 0;
  std::int64_t count = 0;
};

std::vector<RowBlock> every_rank(const Communicator& comm, RowBlock mine) {
  std::vector<RowBlock> all(static_cast<std::size_t>(comm.size()));
  comm.all_gather(&mine, sizeof mine, all.data());
  return all;
}

RowBlock overlap(RowBlock a, RowBlock b) {
  const std::int64_t first = std::max(a.first, b.first);
  const std::int64_t end = std::min(a.first + a.count, b.first + b.count);
  return {first, std::max<std::int64_t>(end - first, 0)};
}

// MPI's counts and offsets, refused on every rank together where one does not fit an int (the
// lattice's limit per rank, require_lattice, keeps them far below).
std::vector<int> mpi_counts(const Communicator& comm, const std::vector<std::int64_t>& n) {
  const bool fit = std::all_of(n.begin(), n.end(), [](std::int64_t v) { return v <= INT_MAX; });
  COATFFT_REQUIRE(comm.all(fit),
                  "split_frf_kernel: more lattice entries to exchange between two "
                  "ranks than MPI's counts take; use more ranks");
  return std::vector<int>(n.begin(), n.end());
}

// The transformed lattice rows `held` (sx entries each, in `lattice`) that are quarter rows j < my
// go, whole and straight from the lattice, to the ranks that hold those rows of the quarter, which
// add norm times their first mx entries, as the serial kernel adds its lattice's
// (split_kernel/short_range.cpp).
void add_to_quarter(const Communicator& comm, const split::SplitPlan& p,
                    const split::ShortRangeLattice& l, RowBlock held, const double* lattice,
                    split::QuarterRows quarter) {
  const std::ptrdiff_t begin = quarter.begin(p);
  const RowBlock wanted{begin, std::max<std::ptrdiff_t>(std::min(quarter.end(p), l.my) - begin, 0)};
  const std::vector<RowBlock> lattices = every_rank(comm, held);
  const std::vector<RowBlock> quarters = every_rank(comm, wanted);
  const auto ranks = static_cast<std::size_t>(comm.size());
  std::vector<std::int64_t> sends(ranks), send_at(ranks), receives(ranks), receive_at(ranks);
  std::int64_t received = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    const RowBlock out = overlap(held, quarters[r]);
    send_at[r] = out.count > 0 ? (out.first - held.first) * l.sx : 0;
    sends[r] = out.count * l.sx;
    receive_at[r] = received;
    receives[r] = overlap(lattices[r], wanted).count * l.sx;
    received += receives[r];
  }
  std::vector<double> receive(static_cast<std::size_t>(std::max<std::int64_t>(received, 1)));
  const std::vector<int> receive_offsets = mpi_counts(comm, receive_at);
  MPI_Alltoallv(lattice, mpi_counts(comm, sends).data(), mpi_counts(comm, send_at).data(),
                MPI_DOUBLE, receive.data(), mpi_counts(comm, receives).data(),
                receive_offsets.data(), MPI_DOUBLE, mpi_comm(comm));
  for (std::size_t r = 0; r < ranks; ++r) {
    const RowBlock in = overlap(lattices[r], wanted);
    const double* values = receive.data() + receive_offsets[r];
    for (std::int64_t j = in.first; j < in.first + in.count; ++j, values += l.sx) {
      double* row = quarter.row(j);
      for (std::ptrdiff_t i = 0; i < l.mx; ++i) row[i] += l.norm * values[i];
    }
  }
}

// (c) R (1 - w) on the quarter's rows. A lattice with a wide axis is one row or column, folded
// whole on every rank; otherwise each rank folds its rows of the (sy, sx) lattice, the 2-D DCT-I
// is taken over the ranks and transposed back to rows, and the rows go where the quarter has them.
void add_short_range(const Communicator& comm, const split::SplitPlan& p,
                     split::QuarterRows quarter) {
  const split::ShortRangeLattice l = split::short_range_lattice(p);
  if (l.empty) return;
  if (l.sx == 1 || l.sy == 1) {
    std::vector<double> spare;
    SplitKernelReport report;
    split::add_short_range(p, quarter, spare, report);
    return;
  }
  const std::ptrdiff_t n[2] = {l.sy, l.sx};
  std::ptrdiff_t rows = 0, n0 = 0, columns = 0, m0 = 0;
  const std::ptrdiff_t doubles =
      fftw_mpi_local_size_many_transposed(2, n, 1, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                          mpi_comm(comm), &rows, &n0, &columns, &m0);
  const auto size = static_cast<std::size_t>(std::max<std::ptrdiff_t>(doubles, 1));
  FftwRealBuffer lattice(size), transposed(size);
  if (rows > 0) split::fold_lattice_rows(p, n0, rows, lattice.data());
  dct1_rows_then_columns(comm, l.sy, l.sx, rows, columns, lattice.data(), transposed.data(),
                         p.threads);
  const FftwPlan to_rows = FftwPlan::create(p.threads, [&] {
    return fftw_mpi_plan_many_transpose(l.sx, l.sy, 1, FFTW_MPI_DEFAULT_BLOCK,
                                        FFTW_MPI_DEFAULT_BLOCK, transposed.data(), lattice.data(),
                                        mpi_comm(comm), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  to_rows.execute();
  add_to_quarter(comm, p, l, {n0, rows}, lattice.data(), quarter);
}

}  // namespace

void split_quarter_rows(const Communicator& comm, const Grid& grid, const Frf& frf,
                        const SplitKernelOptions& options, std::ptrdiff_t y0, std::ptrdiff_t rows,
                        double* out, SplitKernelReport* report_out) {
  const auto start = std::chrono::steady_clock::now();
  const split::SplitPlan plan = split::make_split_plan(grid, frf, options, comm.size());
  split::require_lattice(plan);
  std::fill_n(out, (grid.nx() + 1) * rows, 0.0);
  const split::QuarterRows quarter{out, grid.nx(), y0, rows};
  std::vector<double> spare;
  SplitKernelReport report;
  split::report_plan(plan, report);
  split::assign_singular_terms(plan, quarter);                               // (a) + (b)
  if (plan.long_range) split::add_long_range(plan, quarter, spare, report);  // (c) R w
  if (plan.short_range) add_short_range(comm, plan, quarter);                // (c) R (1 - w)
  report.seconds = seconds_since(start);
  if (report_out != nullptr) *report_out = report;
}

}  // namespace coatfft::detail
