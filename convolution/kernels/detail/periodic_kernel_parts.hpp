#pragma once
// The two parts of the periodic influence kernel (periodic_kernel.hpp, docs/theory.md 4.8) point
// by point, for callers that build all of it (periodic_influence_kernel) or one rank's part of it
// (the distributed periodic operator): the lattice part's spectrum M and the real-space part of
// Ewald's split. The kernel is K = IDFT(M) + real_space, less its mean.
#include <cstddef>
#include <vector>

#include "convolution/kernels/detail/ewald.hpp"
#include "convolution/kernels/periodic_kernel.hpp"

namespace coatfft::detail {

/// erf(alpha r) / r as a function of s = r^2, which it is entire in, for r up to r_max: tabulated
/// on a uniform grid of s (step 5e-4 / alpha^2) and interpolated by cubic Lagrange polynomials,
/// within about 1e-15 of its largest value 2 alpha / sqrt(pi) (the fourth derivative in s is of
/// order alpha^8 times it). The real-space part evaluates it some hundred times a cell; the table
/// is about five times cheaper than erf and the square root. A table of more than a million
/// values (an elongated period) is not built: the function is then evaluated directly.
class ErfOverR {
 public:
  ErfOverR(double alpha, double r_max);
  double operator()(double s) const;

 private:
  double alpha_, step_, inverse_step_;
  std::vector<double> values_;
};

class PeriodicKernelParts {
 public:
  /// Validates as periodic_influence_kernel does (InvalidArgument).
  PeriodicKernelParts(const Grid& grid, const Frf& frf, const PeriodicKernelOptions& options);

  /// M(i, j), 0 <= i <= nx/2, 0 <= j < ny (FFTW's c2r layout, j the signed frequency): the sum
  /// over the aliases of (C erfc(k/(2 alpha))/k + R(k)) S(k), k != 0.
  double spectrum(std::ptrdiff_t i, std::ptrdiff_t j) const;
  /// The real-space part at the offset (i dx, j dy) modulo the period, 0 <= i < nx, 0 <= j < ny.
  double real_space(std::ptrdiff_t i, std::ptrdiff_t j) const;

 private:
  Grid grid_;
  const Frf& frf_;
  double alpha_;
  EwaldLattice lattice_;
  ErfOverR erf_over_r_;
};

}  // namespace coatfft::detail
