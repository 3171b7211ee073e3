// fast_fft_size and fast_even_fft_size against a brute-force search: walk up from n and stop at
// the first length whose only prime factors are 2, 3, 5 and 7 (found by trial division).
#include <catch2/catch.hpp>
#include <cstddef>

#include "core/detail/fft_size.hpp"
#include "core/error.hpp"

using coatfft::detail::fast_even_fft_size;
using coatfft::detail::fast_fft_size;

namespace {

bool is_7_smooth(std::ptrdiff_t m) {
  for (const std::ptrdiff_t p : {2, 3, 5, 7})
    while (m % p == 0) m /= p;
  return m == 1;
}

std::ptrdiff_t brute_force(std::ptrdiff_t n, bool even) {
  std::ptrdiff_t m = n;
  while (!is_7_smooth(m) || (even && m % 2 != 0)) ++m;
  return m;
}

}  // namespace

TEST_CASE("fast_fft_size is the smallest 7-smooth length >= n", "[fft_size]") {
  for (std::ptrdiff_t n = 1; n <= 5000; ++n) {
    INFO("n = " << n);
    REQUIRE(fast_fft_size(n) == brute_force(n, false));
    REQUIRE(fast_even_fft_size(n) == brute_force(n, true));
  }
  // The lengths DC-FFT pads to (2n - 1 up, even) on grids the benchmarks use.
  CHECK(fast_even_fft_size(2 * 127 - 1) == 256);
  CHECK(fast_even_fft_size(2 * 511 - 1) == 1024);
  CHECK(fast_even_fft_size(2 * 33 - 1) == 70);
}

TEST_CASE("fast_fft_size on large n", "[fft_size]") {
  // Values from an independent enumeration of all 7-smooth numbers below 2^54 (Python, sorted
  // set of 2^a 3^b 5^c 7^d, bisection), too far apart for the brute-force walk.
  CHECK(fast_fft_size(1000001) == 1000188);
  CHECK(fast_fft_size(2147483647) == 2147483648);
  CHECK(fast_fft_size(1000000000001) == 1000188000000);
  CHECK(fast_fft_size((std::ptrdiff_t{1} << 52) - 1) == std::ptrdiff_t{1} << 52);
  CHECK(fast_fft_size(std::ptrdiff_t{1} << 52) == std::ptrdiff_t{1} << 52);
}

TEST_CASE("fast_fft_size refuses n < 1 and n > 2^52", "[fft_size][bad_input]") {
  CHECK_THROWS_WITH(fast_fft_size(0), Catch::Contains("n = 0"));
  CHECK_THROWS_AS(fast_fft_size(-3), coatfft::InvalidArgument);
  CHECK_THROWS_AS(fast_fft_size((std::ptrdiff_t{1} << 52) + 1), coatfft::InvalidArgument);
  CHECK_THROWS_WITH(fast_even_fft_size(0), Catch::Contains("n = 0"));
}
