#pragma once
// The two parts of the periodic influence kernel (periodic_kernel.hpp, docs/theory.md 4.8) point
// by point, for callers that build all of it (periodic_influence_kernel) or one rank's part of it
// (the distributed periodic operator): the lattice part's spectrum M and the real-space part of
// Ewald's split. The kernel is K = IDFT(M) + real_space, less its mean.
#include <cstddef>

#include "convolution/kernels/detail/ewald.hpp"
#include "convolution/kernels/periodic_kernel.hpp"

namespace coatfft::detail {

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
};

}  // namespace coatfft::detail
