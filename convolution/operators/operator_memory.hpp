#pragma once
// The memory model of the operators: an upper estimate of the bytes each holds at its peak (its
// construction included), from the sizes alone, so that a front end refuses a grid the machine
// cannot hold (core/memory.hpp) before anything is allocated. Measured against the peak resident
// set of `coatfft run` by scripts/check_estimates_check.py.
#include <cstddef>

#include "../../core/grid.hpp"
#include "make_operator.hpp"

namespace coatfft {

/// An estimate of an operator's memory and the transform lattice that drives it.
struct OperatorMemory {
  double bytes = 0.0;
  std::ptrdiff_t lattice_nx = 0;  ///< transform lengths of apply() (0 for direct summation)
  std::ptrdiff_t lattice_ny = 0;
};

/// make_operator's operator of `options` on `grid`: a real input array, its complex half
/// spectrum and the kernel's half spectrum (2.5 doubles per lattice cell) of the transform
/// lattice, which is the grid itself on a periodic boundary (no padding); on a free one,
/// frf-split and frf-dcfft build their kernel on one more lattice, and frf-dcfft samples the FRF
/// on the alpha-extended lattice.
OperatorMemory estimated_memory(const Grid& grid, const OperatorOptions& options);

/// CerrutiOperator on `grid` [bytes]: nine spectrum quarters, three load spectra of the padded
/// lattice and the three outputs; while it is built, six coefficient fields and four lattice
/// quarters of the layered remainders plus their long-range band.
double estimated_cerruti_bytes(const Grid& grid);

}  // namespace coatfft
