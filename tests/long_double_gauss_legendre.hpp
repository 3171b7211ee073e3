#pragma once
// Gauss-Legendre nodes and weights on [-1, 1] in long double, by Newton's iteration on P_n: the
// tests' far-field references, independent of the library's double-precision tables
// (core/detail/gauss_legendre.hpp).
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

struct LongDoubleRule {
  std::vector<long double> nodes;
  std::vector<long double> weights;
};

inline LongDoubleRule long_double_gauss_legendre(int n) {
  LongDoubleRule rule{std::vector<long double>(static_cast<std::size_t>(n)),
                      std::vector<long double>(static_cast<std::size_t>(n))};
  for (int i = 0; i < n; ++i) {
    long double z = std::cos(std::numbers::pi_v<long double> * (i + 0.75L) / (n + 0.5L));
    long double dp = 1.0L;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1.0L;
      long double p1 = z;
      for (int j = 2; j <= n; ++j) {
        const long double p2 = ((2.0L * j - 1.0L) * z * p1 - (j - 1.0L) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0L);
      const long double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-19L) break;
    }
    rule.nodes[static_cast<std::size_t>(i)] = z;
    rule.weights[static_cast<std::size_t>(i)] = 2.0L / ((1.0L - z * z) * dp * dp);
  }
  return rule;
}
