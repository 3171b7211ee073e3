#pragma once
// The timing of the distributed benchmarks (bench_distributed, bench_distributed_output): the
// median over repeats of one step's time on the slowest rank.
#include <chrono>
#include <vector>

#include "core/detail/timing.hpp"

namespace coatfft::bench {

/// The median over `repeats` of f's time on the slowest rank [ms], after one untimed warm-up:
/// `sync` before each timed call, untimed (a barrier, and whatever must precede the step), `max`
/// the maximum over the ranks (identity serially).
template <typename F, typename Sync, typename Max>
double slowest_rank_median_ms(int repeats, F&& f, Sync&& sync, Max&& max) {
  f();  // warm-up
  std::vector<double> times;
  for (int k = 0; k < repeats; ++k) {
    sync();
    const auto start = std::chrono::steady_clock::now();
    f();
    times.push_back(max(1e3 * detail::seconds_since(start)));
  }
  return detail::median(times);
}

}  // namespace coatfft::bench
