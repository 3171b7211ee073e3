#pragma once
// Error measures shared by tests, benchmarks and the CLI report.
#include "types.hpp"

namespace coatfft {

/// max |a - b| / max |b|  (relative max norm; b is the reference).
inline double rel_linf(const Field& a, const Field& b) {
  return (a - b).abs().maxCoeff() / b.abs().maxCoeff();
}

/// ||a - b||_2 / ||b||_2  (relative l2 norm; b is the reference).
inline double rel_l2(const Field& a, const Field& b) {
  return std::sqrt((a - b).square().sum() / b.square().sum());
}

}  // namespace coatfft
