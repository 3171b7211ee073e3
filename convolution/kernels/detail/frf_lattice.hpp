#pragma once
// The FRF on a frequency lattice, as both FRF pipelines of Spinu (2021) sample it
// (docs/theory.md 4.3, 4.4): the alpha-extended lattice's sizes, its k = 0 value g(0), and H
// sampled on an r2c half spectrum or a quarter of it. Shared by the frf-spectral operator and
// the frf-dcfft influence kernel: a kernel and an operator both build on it, neither on the other.
#include <cstddef>

#include "../../../core/grid.hpp"
#include "../../../core/types.hpp"
#include "../../../frf/frf.hpp"
#include "../g0.hpp"

namespace coatfft {

/// The extended lattice size m = alpha n of one axis; throws InvalidArgument unless alpha is
/// finite, alpha >= `min_alpha` and alpha n is an integer (to 1e-9). `who` names the caller.
std::ptrdiff_t extended_size(std::ptrdiff_t n, double alpha, double min_alpha, const char* who);

/// g(0) by `method` to relative `tolerance` on the alpha-extended lattice of `grid` (spacings
/// 2 pi / (M dx), 2 pi / (M dy), M = extended_size): the k = 0 sample of both FRF pipelines of
/// Spinu (2021) (docs/theory.md section 3). `min_alpha` and `who` as for extended_size.
G0Result lattice_g0(const Grid& grid, const Frf& frf, double alpha, double min_alpha,
                    G0Method method, double tolerance, const char* who);

/// H sampled on the r2c half spectrum of the (mx, my) lattice of a grid with cells dx x dy [m]:
/// entry (jx, jy), jx = 0..mx/2, jy = 0..my-1, is H(|k|) at kx = 2 pi jx / (mx dx),
/// ky = 2 pi jy' / (my dy) with jy' the wrap-around index (docs/conventions.md); the (0, 0) entry
/// is `g0` [m/Pa]. Shape (mx/2 + 1, my), x fastest: FFTW's row-major {my, mx/2 + 1} layout.
/// Evaluates H once per |ky| (and once per unordered pair on a square lattice) on `threads`
/// threads (>= 1; the Frf must then be safe to call concurrently, as those of frf/ are).
Field sample_frf_half_spectrum(const Frf& frf, std::ptrdiff_t mx, std::ptrdiff_t my, double dx,
                               double dy, double g0, int threads = 1);

namespace detail {
/// |j'| for the wrap-around index j of an m-point lattice (j' = j for j < ceil(m/2), else j - m):
/// the row of a quarter that holds the samples of row j, for a spectrum even in that direction.
inline std::ptrdiff_t folded_index(std::ptrdiff_t j, std::ptrdiff_t m) {
  return j < (m + 1) / 2 ? j : m - j;
}

/// H(|k|) at kx = dkx jx, ky = dky jy for jx < qx, jy < qy [m/Pa], x fastest; the singular
/// (0, 0) entry is 0 (the caller puts g(0) there);
/// dkx, dky [rad/m]. On `threads` threads; H(jy, jx) is copied from H(jx, jy) when dkx == dky.
Field sample_frf_quarter(const Frf& frf, std::ptrdiff_t qx, std::ptrdiff_t qy, double dkx,
                         double dky, int threads);
}  // namespace detail

}  // namespace coatfft
