#include "contact/detail/initial_pressure.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact/detail/solver_ranks.hpp"

namespace coatfft::detail {

Field hertzian_profile(const Field& h, double level) {
  return (level - h).max(0.0).sqrt();
}

namespace {

// The doubles in their order as unsigned integers (sign-magnitude to offset binary), and back.
std::uint64_t ordered(double x) {
  const auto u = std::bit_cast<std::uint64_t>(x);
  return (u >> 63) != 0 ? ~u : u | (std::uint64_t{1} << 63);
}
double from_ordered(std::uint64_t key) {
  return std::bit_cast<double>((key >> 63) != 0 ? key & ~(std::uint64_t{1} << 63) : ~key);
}

// The k-th smallest value of a field distributed over `ranks`: the least value v with more than
// k cells <= v, by bisection on the doubles' order (at most 64 counting passes, each a reduction):
// no rank gathers the field, and the value is the one nth_element finds on the whole field.
double kth_smallest(const Field& h, std::ptrdiff_t k, const SolverRanks* ranks) {
  const RankExtrema e = extrema_over(ranks, h);
  std::uint64_t lo = ordered(e.min), hi = ordered(e.max);
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    const double v = from_ordered(mid);
    if (count_over(ranks, (h <= v).count()) > k) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return from_ordered(lo);
}

}  // namespace

double level_below(const Field& h, double share, const SolverRanks* ranks) {
  const std::ptrdiff_t cells = count_over(ranks, h.size());
  const auto k = static_cast<std::ptrdiff_t>(share * static_cast<double>(cells));
  if (ranks != nullptr) return kth_smallest(h, k, ranks);
  std::vector<double> values(h.data(), h.data() + h.size());
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

double level_correction(const Field& h, const Field& p, const Field& u, const SolverRanks* ranks) {
  const auto support = p > 0;
  const auto n = static_cast<double>(count_over(ranks, support.count()));
  const double h_mean = sum_over(ranks, support.select(h, 0.0).sum()) / n;
  const double u_mean = sum_over(ranks, support.select(u, 0.0).sum()) / n;
  const double covariance = sum_over(ranks, support.select((h - h_mean) * (u - u_mean), 0.0).sum());
  const double variance = sum_over(ranks, support.select((h - h_mean).square(), 0.0).sum());
  const double slope = -covariance / variance;
  return std::isfinite(slope) && slope > 0 ? std::cbrt(slope * slope) : 1.0;
}

}  // namespace coatfft::detail
