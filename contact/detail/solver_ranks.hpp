#pragma once
// What a contact solve needs of the ranks it shares its fields with, when the fields are
// distributed in row slabs (distributed/distributed_contact.hpp): the sums, counts and maxima of
// its passes combined over the ranks, and a preconditioner of the distributed fields. MPI-free:
// the distributed layer implements it; a serial solve has none (a null pointer), and every
// function here then returns what this process alone holds.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "../../convolution/fft/planning.hpp"
#include "../../core/grid.hpp"

namespace coatfft {
class SurfaceOperator;
}  // namespace coatfft

namespace coatfft::detail {

/// z <- P z in place (contact/detail/fourier_preconditioner.hpp).
class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  /// `z`: a field of the solve's field shape (this rank's rows), overwritten by P z.
  virtual void apply(double* z) = 0;
};

class SolverRanks {
 public:
  virtual ~SolverRanks() = default;
  virtual int count() const = 0;
  /// Every rank's `size` bytes at `mine`, in rank order, into `all` (count() * size bytes).
  virtual void all_gather(const void* mine, std::size_t size, void* all) const = 0;
  /// This rank's rows of the grid: y0 <= j < y0 + rows.
  virtual std::ptrdiff_t first_row() const = 0;
  virtual std::ptrdiff_t rows() const = 0;
  /// The half-space preconditioner of the distributed fields of `op` (sharing its transforms
  /// where it can).
  virtual std::unique_ptr<Preconditioner> preconditioner(const SurfaceOperator& op, int threads,
                                                         Planning planning) const = 0;
  /// The same ranks holding the fields of another distributed operator `op` (its own rows): a
  /// nested start's coarse operator.
  virtual std::shared_ptr<const SolverRanks> of(const SurfaceOperator& op) const = 0;
};

/// `mine` combined over the ranks by Sums' += in rank order (the same on every rank, and for a
/// given rank count the same bits every time); `mine` itself without ranks. Sums is trivially
/// copyable (the passes' sums, counts, maxima and flags).
template <class Sums>
Sums over_ranks(const SolverRanks* ranks, const Sums& mine) {
  if (ranks == nullptr) return mine;
  std::vector<Sums> all(static_cast<std::size_t>(ranks->count()));
  ranks->all_gather(&mine, sizeof(Sums), all.data());
  Sums total{};
  for (const Sums& part : all) total += part;
  return total;
}

/// Sums, minima, maxima and counts of single values over the ranks.
struct RankSum {
  double value = 0.0;
  RankSum& operator+=(const RankSum& o) {
    value += o.value;
    return *this;
  }
};
struct RankCount {
  std::ptrdiff_t value = 0;
  RankCount& operator+=(const RankCount& o) {
    value += o.value;
    return *this;
  }
};
struct RankExtrema {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  RankExtrema& operator+=(const RankExtrema& o) {
    min = std::min(min, o.min);
    max = std::max(max, o.max);
    return *this;
  }
};
struct RankAll {
  bool value = true;
  RankAll& operator+=(const RankAll& o) {
    value = value && o.value;
    return *this;
  }
};

inline double sum_over(const SolverRanks* r, double mine) {
  return over_ranks(r, RankSum{mine}).value;
}
inline std::ptrdiff_t count_over(const SolverRanks* r, std::ptrdiff_t mine) {
  return over_ranks(r, RankCount{mine}).value;
}
inline bool all_over(const SolverRanks* r, bool mine) {
  return over_ranks(r, RankAll{mine}).value;
}
/// min and max of a field over the ranks (a rank with no cells adds +inf and -inf).
template <class F>
RankExtrema extrema_over(const SolverRanks* r, const F& f) {
  RankExtrema e;
  if (f.size() > 0) e = {f.minCoeff(), f.maxCoeff()};
  return over_ranks(r, e);
}

}  // namespace coatfft::detail
