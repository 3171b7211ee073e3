// The private numerics of core/detail: the parallel loops, the Gauss-Legendre rules, the
// six-point Lagrange interpolation and the timing helpers.
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <vector>

#include "core/detail/gauss_legendre.hpp"
#include "core/detail/lagrange.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"

using namespace coatfft;

TEST_CASE("parallel_for visits every index once, on any number of threads", "[detail]") {
  for (const int threads : {1, 2, 3, 7, 64}) {
    std::vector<int> hits(37, 0);
    detail::parallel_for(3, 37, threads, [&](std::ptrdiff_t i) { ++hits[i]; });
    for (std::size_t i = 0; i < hits.size(); ++i) CHECK(hits[i] == (i >= 3 ? 1 : 0));
  }
  int calls = 0;
  detail::parallel_for(5, 5, 4, [&](std::ptrdiff_t) { ++calls; });
  CHECK(calls == 0);
}

TEST_CASE("parallel_chunks covers the range with contiguous chunks, one per worker", "[detail]") {
  std::vector<int> owner(100, -1);
  std::atomic<int> chunks{0};
  detail::parallel_chunks(0, 100, 3,
                          [&](std::ptrdiff_t w, std::ptrdiff_t first, std::ptrdiff_t last) {
                            ++chunks;
                            CHECK(first == 100 * w / 3);
                            CHECK(last == 100 * (w + 1) / 3);
                            for (std::ptrdiff_t i = first; i < last; ++i)
                              owner[i] = static_cast<int>(w);
                          });
  CHECK(chunks == 3);
  for (int o : owner) CHECK(o >= 0);
}

TEST_CASE("parallel loops rethrow a worker's exception after the join", "[detail]") {
  for (const int threads : {1, 4}) {
    std::atomic<int> done{0};
    const auto body = [&](std::ptrdiff_t i) {
      if (i == 5) throw InvalidArgument("refused");
      ++done;
    };
    CHECK_THROWS_AS(detail::parallel_for(0, 20, threads, body), InvalidArgument);
    // The throwing worker stops (inline: at 5; of 4 workers, worker 1 skips 9, 13, 17); the
    // others finish their indices: they were joined before the rethrow.
    CHECK(done == (threads == 1 ? 5 : 16));
  }
}

TEST_CASE("Gauss-Legendre rules integrate polynomials of degree 2n - 1 exactly", "[detail]") {
  for (const int n : {1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 16, 20}) {
    INFO("n = " << n);
    const detail::GaussLegendreView rule = detail::gauss_legendre(n);
    REQUIRE(rule.nodes.size() == static_cast<std::size_t>(n));
    for (int d = 0; d < 2 * n; ++d) {
      double sum = 0.0;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i)
        sum += rule.weights[i] * std::pow(rule.nodes[i], d);
      const double exact = d % 2 == 0 ? 2.0 / (d + 1) : 0.0;
      CHECK(std::abs(sum - exact) <= 4e-16 * n);
    }
    for (std::size_t i = 1; i < rule.nodes.size(); ++i) CHECK(rule.nodes[i] > rule.nodes[i - 1]);
  }
  // Abramowitz & Stegun (1964) 25.4.30, 6 points, to the last digit of double.
  const auto& g6 = detail::gauss_legendre<6>();
  CHECK(g6.nodes[5] == 0.932469514203152028);
  CHECK(g6.weights[5] == 0.171324492379170345);
  CHECK_THROWS_AS(detail::gauss_legendre(9), InvalidArgument);
}

TEST_CASE("six-point Lagrange interpolation is exact for quintics", "[detail]") {
  const auto quintic = [](double x) {
    return 1.0 - 2.0 * x + 0.5 * x * x * x - 0.1 * std::pow(x, 5);
  };
  const double f[6] = {quintic(-2), quintic(-1), quintic(0), quintic(1), quintic(2), quintic(3)};
  for (const double t : {0.0, 0.25, 0.5, 0.999, -1.5, 2.5}) {
    INFO("t = " << t);
    CHECK(detail::lagrange6(f, t) == Approx(quintic(t)).epsilon(1e-14));
  }
  // At a node the weights are 0 and 1.
  const std::array<double, 6> w = detail::lagrange6_weights(1.0);
  CHECK(w[3] == 1.0);
  CHECK(w[0] == 0.0);
}

TEST_CASE("median of timings", "[detail]") {
  CHECK(detail::median({3.0, 1.0, 2.0}) == 2.0);
  // Robust to outliers, which is why timings report it: one slow run in five does not move it.
  CHECK(detail::median({1.0, 1e9, 2.0, 3.0, 1e12}) == 3.0);
  CHECK(detail::median({4.0, 1.0, 2.0, 3.0}) == 2.5);
  CHECK(detail::median({}) == 0.0);
  CHECK(detail::seconds_since(std::chrono::steady_clock::now()) >= 0.0);
}
