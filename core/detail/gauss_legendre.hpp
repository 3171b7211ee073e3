#pragma once
// Gauss-Legendre rules on [-1, 1] from Boost.Math (private: not installed). The nodes and
// weights are Boost's in long double (tabulated or found by Newton's iteration on P_n), rounded
// once to double: within half an ulp of the exact values, as the tables of Abramowitz & Stegun
// (1964, 25.4.30) that they replace.
#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cstddef>
#include <span>

#include "core/error.hpp"

namespace coatfft::detail {

/// The N-point Gauss-Legendre rule on [-1, 1]: nodes ascending, weights[i] that of nodes[i].
template <int N>
struct GaussLegendreRule {
  std::array<double, N> nodes{};
  std::array<double, N> weights{};
};

/// The N-point rule, computed once per N (thread-safe static initialisation).
template <int N>
const GaussLegendreRule<N>& gauss_legendre() {
  static_assert(N >= 1, "a Gauss-Legendre rule needs at least one node");
  static const GaussLegendreRule<N> rule = [] {
    // Boost stores the (N + 1)/2 nodes x >= 0 with their weights; the rule is symmetric.
    using Boost = boost::math::quadrature::gauss<long double, N>;
    const auto& x = Boost::abscissa();
    const auto& w = Boost::weights();
    std::array<std::pair<double, double>, N> pairs{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      pairs[n++] = {static_cast<double>(x[i]), static_cast<double>(w[i])};
      if (x[i] != 0) pairs[n++] = {-static_cast<double>(x[i]), static_cast<double>(w[i])};
    }
    std::sort(pairs.begin(), pairs.end());
    GaussLegendreRule<N> r;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      r.nodes[i] = pairs[i].first;
      r.weights[i] = pairs[i].second;
    }
    return r;
  }();
  return rule;
}

/// A rule of run-time size: views of a gauss_legendre<N>() (valid for the program's lifetime).
struct GaussLegendreView {
  std::span<const double> nodes;
  std::span<const double> weights;
};

/// The n-point rule on [-1, 1] for n in 1..8, 10, 12, 16, 20 (the sizes the library uses, and
/// their neighbours); throws InvalidArgument for any other n.
inline GaussLegendreView gauss_legendre(int n) {
  const auto view = [](const auto& rule) {
    return GaussLegendreView{std::span<const double>(rule.nodes),
                             std::span<const double>(rule.weights)};
  };
  switch (n) {
    case 1:
      return view(gauss_legendre<1>());
    case 2:
      return view(gauss_legendre<2>());
    case 3:
      return view(gauss_legendre<3>());
    case 4:
      return view(gauss_legendre<4>());
    case 5:
      return view(gauss_legendre<5>());
    case 6:
      return view(gauss_legendre<6>());
    case 7:
      return view(gauss_legendre<7>());
    case 8:
      return view(gauss_legendre<8>());
    case 10:
      return view(gauss_legendre<10>());
    case 12:
      return view(gauss_legendre<12>());
    case 16:
      return view(gauss_legendre<16>());
    case 20:
      return view(gauss_legendre<20>());
    default:
      break;
  }
  throw InvalidArgument(
      concat("gauss_legendre: no ", n, "-point rule (n must be 1..8, 10, 12, 16 or 20)"));
}

}  // namespace coatfft::detail
