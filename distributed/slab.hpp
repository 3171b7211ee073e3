#pragma once
// Which part of a distributed (nx, ny) field one rank holds: a slab of whole rows along y, and
// after the transforms' transpose a slab of whole columns of the half spectrum (nx/2 + 1 columns
// of ny entries). The blocks are FFTW-MPI's defaults (FFTW manual 6.4): ceil(n / P) rows or
// columns a rank in rank order, so the last ranks may hold fewer, or none.
#include <cstddef>

#include "../core/types.hpp"
#include "communicator.hpp"

namespace coatfft {

struct Slab {
  std::ptrdiff_t nx = 0, ny = 0;        ///< the whole grid's cells
  std::ptrdiff_t y0 = 0, rows = 0;      ///< this rank's rows y0 <= j < y0 + rows
  std::ptrdiff_t kx0 = 0, columns = 0;  ///< its half-spectrum columns kx0 <= i < kx0 + columns

  std::ptrdiff_t cells() const { return nx * rows; }
  /// An empty field of this rank's part of the grid: (nx, rows), x fastest as a whole Field.
  Field field() const { return Field::Zero(nx, rows); }
};

/// This rank's slab of a (nx, ny) grid shared by `comm`. InvalidArgument for nx or ny < 2.
Slab slab_of(const Communicator& comm, std::ptrdiff_t nx, std::ptrdiff_t ny);

}  // namespace coatfft
