#pragma once
// Fast FFT lengths. FFTW's codelets cover the radices 2, 3, 5 and 7 (and 11, 13 less well); a
// length with a larger prime factor falls back to Rader's or Bluestein's algorithm and costs
// several times more (Frigo & Johnson 2005). Padding a transform up to a 7-smooth length (a
// product 2^a 3^b 5^c 7^d) is the usual cure, as in pocketfft's good_size and SciPy's
// next_fast_len.
#include <cstddef>

#include "core/error.hpp"

namespace coatfft::detail {

/// The smallest product 2^a 3^b 5^c 7^d >= n. Throws InvalidArgument unless 1 <= n <= 2^52 (the
/// answer then stays below 2^53 and representable everywhere a length is used).
inline std::ptrdiff_t fast_fft_size(std::ptrdiff_t n) {
  constexpr std::ptrdiff_t limit = std::ptrdiff_t{1} << 52;
  COATFFT_REQUIRE(n >= 1 && n <= limit, "fast_fft_size: n = ", n, ", but n must be in 1..", limit);
  // Walk over the 7-smooth numbers 7^d 5^c 3^b below 2n, completing each with the power of two
  // that reaches n: at most ~log(n)^3 / 6 candidates, so no table is needed.
  std::ptrdiff_t best = std::ptrdiff_t{1};
  while (best < n) best *= 2;  // 2^a >= n, itself a candidate
  for (std::ptrdiff_t p7 = 1; p7 < best; p7 *= 7)
    for (std::ptrdiff_t p75 = p7; p75 < best; p75 *= 5)
      for (std::ptrdiff_t p753 = p75; p753 < best; p753 *= 3) {
        std::ptrdiff_t m = p753;
        while (m < n) m *= 2;
        if (m < best) best = m;
      }
  return best;
}

/// The smallest *even* product 2^a 3^b 5^c 7^d >= n, i.e. 2 fast_fft_size(ceil(n / 2)); same
/// range as fast_fft_size. DC-FFT pads to even lengths only: an even kernel on an even period M
/// is transformed by a DCT-I of its first M/2 + 1 entries (FFTW has no r2r transform for an even
/// sequence of odd period), and FFTW's real transforms of even length run as complex ones of
/// half the length. The constraint costs little: for 50 <= n <= 5000 the smallest even fast
/// size >= 2n - 1 exceeds the smallest fast size >= 2n - 1 by 7% at most (n = 113: 240, not
/// 225), and for every n <= 5000 it exceeds 2n by 9% at most (n = 22: 48, not 44).
inline std::ptrdiff_t fast_even_fft_size(std::ptrdiff_t n) {
  COATFFT_REQUIRE(n >= 1, "fast_even_fft_size: n = ", n, ", but n must be >= 1");
  return 2 * fast_fft_size(n / 2 + n % 2);
}

}  // namespace coatfft::detail
