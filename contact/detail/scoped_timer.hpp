#pragma once
// The timings of a contact solve (ContactTimings): the wall time of a scope, added to its bucket.
#include <chrono>

#include "core/detail/timing.hpp"

namespace coatfft::detail {

// Adds the wall time of its scope to `bucket` [s].
class ScopedTimer {
 public:
  explicit ScopedTimer(double& bucket)
      : bucket_(bucket), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { bucket_ += detail::seconds_since(start_); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& bucket_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace coatfft::detail
