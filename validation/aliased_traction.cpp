#include "validation/aliased_traction.hpp"

#include <cmath>
#include <numbers>

#include "core/detail/sinc.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace coatfft {

namespace {

// The FRFs of the six kernels at (kx, ky), k = |k| > 0 (frf/traction_response.hpp).
std::array<Complex, 6> frfs(const TractionResponse& r, double kx, double ky) {
  const double k = std::hypot(kx, ky), c = kx / k, s = ky / k;
  const TractionFrfs f = r(k);
  const Complex i(0.0, 1.0);
  return {f.zz,
          f.s + f.d * (c * c - s * s),
          f.s - f.d * (c * c - s * s),
          f.d * 2.0 * c * s,
          -i * f.c * c,
          -i * f.c * s};
}

}  // namespace

std::array<Complex, 6> alias_sum(const Grid& g, const TractionResponse& r, int m, int n, int P,
                                 int Q) {
  COATFFT_REQUIRE(m != 0 || n != 0, "alias_sum: the lattice point k = 0 has no finite sum");
  using std::numbers::pi;
  std::array<Complex, 6> sum{};
  for (int p = -P; p <= P; ++p)
    for (int q = -Q; q <= Q; ++q) {
      const double kx = 2 * pi * (double(m) / g.lx() + double(p) / g.dx());
      const double ky = 2 * pi * (double(n) / g.ly() + double(q) / g.dy());
      const double cell = detail::sinc(0.5 * kx * g.dx()) * detail::sinc(0.5 * ky * g.dy());
      if (cell == 0.0) continue;
      const auto f = frfs(r, kx, ky);
      for (int c = 0; c < 6; ++c) sum[c] += cell * f[c];
    }
  return sum;
}

std::array<Complex, 6> aligned_alias_sum(const Grid& g, const TractionResponse& r, int m, int n,
                                         int P) {
  COATFFT_REQUIRE(m == 0 || n == 0, "aligned_alias_sum: the lattice point is not on an axis");
  const bool along_x = n == 0;
  const auto a = alias_sum(g, r, m, n, along_x ? P : 0, along_x ? 0 : P);
  const auto b = alias_sum(g, r, m, n, along_x ? P + 1 : 0, along_x ? 0 : P + 1);
  std::array<Complex, 6> mean;
  for (int c = 0; c < 6; ++c) mean[c] = 0.5 * (a[c] + b[c]);
  return mean;
}

}  // namespace coatfft
