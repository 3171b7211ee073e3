#pragma once
// Wall-clock timing helpers shared by the library's reports and the programs (private: not
// installed).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/interrupt.hpp"
#include "core/types.hpp"

namespace coatfft::detail {

/// Seconds of the steady clock elapsed since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The median of `values` (the mean of the two middle ones for an even count); 0 when empty.
/// Timings are summarised by medians: robust to the other processes sharing a machine.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 != 0 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Median wall time [s] of `repeat` (>= 1) applications of `op` (any SurfaceOperator) to
/// `pressure`; the last result is left in `displacement`. Throws Interrupted between two
/// applications when asked to stop (core/interrupt.hpp).
template <class Operator>
double time_applications(Operator& op, const Field& pressure, Field& displacement, int repeat) {
  std::vector<double> seconds;
  seconds.reserve(static_cast<std::size_t>(std::max(repeat, 0)));
  for (int r = 0; r < repeat; ++r) {
    check_interrupt();
    const auto start = std::chrono::steady_clock::now();
    op.apply(pressure, displacement);
    seconds.push_back(seconds_since(start));
  }
  return median(std::move(seconds));
}

}  // namespace coatfft::detail
