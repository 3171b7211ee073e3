#pragma once
// sin(x)/x, the transform of a uniform cell over its width (private: not installed).
#include <cmath>

namespace coatfft::detail {

/// sin(x)/x, 1 at x = 0; its series 1 - x^2/6 below 1e-8, where both round to 1.
inline double sinc(double x) {
  return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x;
}

}  // namespace coatfft::detail
