#pragma once
// The work fields of a contact solve's iteration and the element-wise passes over their cells
// (contact/polonsky_keer_iteration.cpp): fields and masks on huge pages, the sums a pass adds
// chunk by chunk, and the pass itself on ContactOptions::threads.
#include <cstddef>
#include <vector>

#include "contact/detail/solver_ranks.hpp"
#include "core/detail/huge_pages.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/types.hpp"

namespace coatfft::detail {

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;
using ByteMask = Eigen::Array<unsigned char, Eigen::Dynamic, 1>;  // one byte a cell
using SingleField = Eigen::Array<float, Eigen::Dynamic, 1>;       // four bytes a cell

// A work field of h's shape on huge pages (core/detail/huge_pages.hpp), its values unset, and
// the same zeroed; a cell mask of h's size, cleared; a single-precision field of h's size, zeroed.
inline Field work_field(const Field& h) {
  return untouched_array<Field>(h.rows(), h.cols());
}
inline Field zero_field(const Field& h) {
  return zeroed_array<Field>(h.rows(), h.cols());
}
inline ByteMask clear_mask(const Field& h) {
  return zeroed_array<ByteMask>(h.size(), 1);
}
inline SingleField zero_single_field(const Field& h) {
  return zeroed_array<SingleField>(h.size(), 1);
}

// The fewest cells whose element-wise passes run on ContactOptions::threads: a pass over 512^2
// cells takes about a millisecond, against tens of microseconds to start a thread.
inline constexpr std::ptrdiff_t kParallelCells = 512 * 512;

// Mean of f over the cells where mask is set, `count` of them over the ranks (> 0).
inline double masked_mean(const Field& f, const Mask& mask, std::ptrdiff_t count,
                          const SolverRanks* r) {
  return sum_over(r, mask.select(f, 0.0).sum()) / static_cast<double>(count);
}

// Sums of a pass over the cells, added chunk by chunk (count and sum, or maxima, or nothing).
struct CountSum {
  std::ptrdiff_t count = 0;
  double sum = 0.0;
  CountSum& operator+=(const CountSum& o) {
    count += o.count;
    sum += o.sum;
    return *this;
  }
};
struct NoSums {
  NoSums& operator+=(const NoSums&) { return *this; }
};

// Runs pass(first, last, sums) on contiguous chunks of the n cells, one per worker, and adds the
// chunks' sums in chunk order (the same result for the same number of workers). The passes are
// bound by memory bandwidth, which a second core raises; with one worker the pass runs inline.
template <class Sums, class Pass>
Sums over_cells(std::ptrdiff_t n, int workers, const Pass& pass) {
  std::vector<Sums> parts(static_cast<std::size_t>(workers));
  detail::parallel_chunks(0, n, workers,
                          [&](std::ptrdiff_t w, std::ptrdiff_t first, std::ptrdiff_t last) {
                            pass(first, last, parts[static_cast<std::size_t>(w)]);
                          });
  Sums total{};
  for (const Sums& part : parts) total += part;
  return total;
}

}  // namespace coatfft::detail
