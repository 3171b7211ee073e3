#pragma once
// The reference of the periodic 3 x 3 surface response (periodic_traction_kernels): at a lattice
// wavevector of a periodic grid, the transform of each influence kernel is the FRF times the
// cell's transform summed over every alias k + 2 pi (p/dx, q/dy) (docs/theory.md 4.8). Summed
// here term by term, independently of the Ewald split the kernels use.
#include <array>
#include <complex>

#include "../core/grid.hpp"
#include "../frf/traction_response.hpp"

namespace coatfft {

/// The alias series, |p| <= P, |q| <= Q, of the six kernels' FRFs (TractionKernels' order zp, xx,
/// yy, yx, zx, zy; forward transform exp(-i k.x)) at the lattice point k = 2 pi (m/lx, n/ly) of
/// `grid`, k != 0. Along an axis (n = 0 with Q = 0, or m = 0 with P = 0) the series alternates
/// (the cell's transform flips sign from one alias to the next): the mean of the sums to P and
/// P + 1 is then within about (1/P)^3 of its limit (aligned_alias_sum).
std::array<std::complex<double>, 6> alias_sum(const Grid& grid, const TractionResponse& response,
                                              int m, int n, int P, int Q);

/// The series along an axis (m = 0 or n = 0) summed to that accuracy from P aliases.
std::array<std::complex<double>, 6> aligned_alias_sum(const Grid& grid,
                                                      const TractionResponse& response, int m,
                                                      int n, int P);

}  // namespace coatfft
