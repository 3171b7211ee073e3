#pragma once
// Influence coefficients of a periodic surface: the displacement at the cell centres under a unit
// pressure uniform over the cell at the origin and over all its periodic images, for any FRF
// (docs/theory.md 4.8). Exact for a periodic problem: the FRF times the cell's transform on the
// periodic lattice, every alias k + 2 pi (p/dx, q/dy) included, nothing periodised twice. The
// k = 0 term, the mean displacement, is infinite for a half-space (a net force on a periodic
// surface sinks it without bound): it is left out, so the displacement has zero mean over the
// period, and contact solvers measure the approach from the mean plane of the deformed surface.
//
// H = C/k + R(k), C = Cinf (the top medium):
//   C/k, the homogeneous half-space, by Ewald's (1921) split of its kernel C/(2 pi r):
//     erfc(alpha r)/r in space (Love's closed-form cell integral of 1/r less a Gauss-Legendre rule
//     of the smooth erf(alpha r)/r, over the 3 x 3 nearest images) and its complement
//     2 pi erfc(k/(2 alpha))/k on the lattice (a Gaussian-fast alias sum);
//   R, which decays like exp(-2 k h_top), on the lattice with its aliases.
#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../../frf/frf.hpp"

namespace coatfft {

struct PeriodicKernelOptions {
  /// Relative size [-] of the terms left out (of the remainder's alias series, of the Ewald
  /// sums' tails), against Cinf; in (0, 1e-6].
  double tolerance = 1e-12;
  /// Most FRF evaluations of the remainder's lattice (estimated first; InvalidArgument beyond):
  /// the aliased lattice points within the remainder's reach k_max (about 6/h for a top coating
  /// h thick), pi/2 (k_max L/(2 pi))^2 for a period L: a coating much thinner than a cell needs
  /// about (6 dx/h)^2 aliases per lattice point.
  double max_evaluations = 2e8;
  int threads = 1;  ///< in [1, max_threads]
};

/// K(i, j) [m/Pa], 0 <= i < nx, 0 <= j < ny: the displacement at the offset (i dx, j dy) modulo
/// the period, with zero sum over the period. Even in both offsets. InvalidArgument for bad
/// options, an FRF whose c_inf() is not finite and > 0, or a remainder too costly.
Field periodic_influence_kernel(const Grid& grid, const Frf& frf,
                                const PeriodicKernelOptions& options = {});

}  // namespace coatfft
