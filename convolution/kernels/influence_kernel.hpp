#pragma once
// Influence coefficients of a surface operator on a Grid. Every kernel coatfft makes is even,
// K(-di, dj) = K(di, -dj) = K(di, dj) (a radial Green's function on a symmetric cell), so it is
// stored once, as its quarter di, dj >= 0, in one of two forms:
//  - coefficients: quarter(di, dj) = K(di, dj) [m/Pa], the displacement at cell (i, j) per unit
//    pressure on cell (i - di, j - dj);
//  - spectrum: quarter(jx, jy) = sum over the offsets of K(di, dj) cos(pi jx di / nx)
//    cos(pi jy dj / ny) [m/Pa], the kernel's (real, even) DFT on DC-FFT's padded (2nx, 2ny)
//    lattice (Liu, Wang & Liu 2000; docs/theory.md section 4).
// Both are arrays of shape (nx + 1, ny + 1), x fastest. In the coefficient form the entries
// di = nx and dj = ny are offsets the linear convolution of nx x ny cells never uses (0 by
// convention); in the spectrum form whatever the spectrum implies at the offsets +-nx, +-ny is
// irrelevant for the same reason. A DC-FFT transforms the coefficient form by a DCT-I, which on
// the 2n lattice is exactly the spectrum form; on a longer padded lattice (a fast FFT length,
// DcfftOperator::padded_size) the coefficients are zero-padded first, and a spectrum form keeps
// its 2n lattice.
#include <cstddef>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../method.hpp"

namespace coatfft {

class InfluenceKernel {
 public:
  enum class Form { coefficients, spectrum };

  /// Validates the quarter: shape (nx + 1, ny + 1) of `grid` and finite entries (throws
  /// InvalidArgument otherwise). `method` is the method whose coefficients these are (what an
  /// operator built on the kernel reports). In the coefficient form the unused entries di = nx
  /// and dj = ny are set to 0.
  InfluenceKernel(const Grid& grid, Form form, Field quarter, Method method = Method::dcfft);

  const Grid& grid() const { return grid_; }
  Form form() const { return form_; }
  Method method() const { return method_; }
  /// The stored quarter, shape (nx + 1, ny + 1), x fastest.
  const Field& quarter() const { return quarter_; }

  /// K(di, dj) [m/Pa] for |di| <= nx - 1, |dj| <= ny - 1 (coefficient form only; throws
  /// InvalidArgument otherwise).
  double at(std::ptrdiff_t di, std::ptrdiff_t dj) const;
  /// The (2nx, 2ny) wrap-around array of the coefficient form (slot d for d >= 0, 2n + d for
  /// d < 0; slots nx and ny hold 0): the circular kernel DC-FFT transforms, written out for the
  /// direct sum and for tests. Throws InvalidArgument for the spectrum form.
  Field wrapped() const;

 private:
  Grid grid_;
  Form form_;
  Field quarter_;
  Method method_;
};

/// Love's coefficients for a homogeneous half-space of plane-strain modulus E* [Pa]:
/// K(di, dj) = love_influence(di dx, dj dy, dx, dy) / E* (docs/theory.md (1.5)), coefficient
/// form, Method::dcfft. Throws InvalidArgument unless E* is finite and > 0. `threads` (>= 1)
/// threads share the columns; the result does not depend on it.
InfluenceKernel love_kernel(const Grid& grid, double plane_strain_modulus, int threads = 1);

}  // namespace coatfft
