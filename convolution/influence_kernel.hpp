#pragma once
// Influence coefficients of a surface operator on a Grid, in the wrap-around layout that DC-FFT
// (Liu, Wang & Liu 2000) transforms: the linear convolution u_ij = sum_kl K(i-k, j-l) p_kl over an
// nx x ny grid equals a circular one over a (2nx, 2ny) grid with K stored at slot(d).
#include <cstddef>

#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft {

/// K(di, dj) [m/Pa]: displacement at cell (i, j) per unit pressure on cell (i - di, j - dj), for
/// |di| <= nx - 1, |dj| <= ny - 1. Stored in a (2nx, 2ny) Field at slot(d) = d for d >= 0 and
/// 2n + d for d < 0; the slots nx (along x) and ny (along y) are never used by the linear
/// convolution and hold 0. No symmetry is assumed.
class InfluenceKernel {
 public:
  /// `wrapped` must have shape (2 nx, 2 ny) of `grid` and finite entries (throws
  /// InvalidArgument otherwise); its unused slots nx and ny are set to 0.
  InfluenceKernel(const Grid& grid, Field wrapped);

  /// K(di, dj) [m/Pa]; throws InvalidArgument unless |di| <= nx - 1 and |dj| <= ny - 1.
  double at(std::ptrdiff_t di, std::ptrdiff_t dj) const;
  /// The (2nx, 2ny) wrap-around array, x fastest.
  const Field& wrapped() const { return wrapped_; }
  const Grid& grid() const { return grid_; }

 private:
  Grid grid_;
  Field wrapped_;
};

/// A kernel even in x and in y, K(-di, dj) = K(di, -dj) = K(di, dj) (Love's, and every radial
/// kernel on a symmetric cell), stored as its quarter di, dj >= 0: `quarter` has shape
/// (nx + 1, ny + 1) and quarter(di, dj) = K(di, dj); the entries di = nx and dj = ny are never used
/// by the convolution (0 by convention). A quarter of the (2nx, 2ny) wrap-around array, and
/// DcfftOperator transforms it directly (a DCT-I of the quarter is the kernel's spectrum).
struct EvenInfluenceKernel {
  Grid grid;
  Field quarter;
};

/// The wrap-around form of an even kernel (for DirectOperator, or any consumer of
/// InfluenceKernel). Throws InvalidArgument unless the quarter has shape (nx + 1, ny + 1).
InfluenceKernel wrap_even_kernel(const EvenInfluenceKernel& kernel);

/// Love's coefficients for a homogeneous half-space of plane-strain modulus E* [Pa]:
/// K(di, dj) = love_influence(di dx, dj dy, dx, dy) / E* (theory.md 1.5). Throws
/// InvalidArgument unless E* is finite and > 0. `threads` (>= 1) threads share the rows; the
/// result does not depend on it.
InfluenceKernel love_kernel(const Grid& grid, double plane_strain_modulus, int threads = 1);

/// The same coefficients as an EvenInfluenceKernel (what DcfftOperator needs: no (2nx, 2ny)
/// array is formed, a quarter of the memory and of the page faults).
EvenInfluenceKernel love_kernel_quarter(const Grid& grid, double plane_strain_modulus,
                                        int threads = 1);

}  // namespace coatfft
