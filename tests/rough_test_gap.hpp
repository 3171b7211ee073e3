#pragma once
// The rough gaps of the contact solver's tests: a rigid flat on a periodic self-affine surface
// (rms slope 0.05, roll-off at a quarter of the period) with the shortest wavelength
// `short_cells` cells, h = max(z) - z.
#include "core/grid.hpp"
#include "core/types.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace coatfft::test {

inline Field rough_test_gap(const Grid& grid, int short_cells, unsigned seed) {
  SelfAffineSpec spec;
  spec.rms_slope = 0.05;
  spec.short_cutoff = short_cells * grid.dx();
  spec.long_cutoff = grid.lx() / 4;
  spec.seed = seed;
  const Field z = self_affine_surface(grid, spec);
  return z.maxCoeff() - z;
}

}  // namespace coatfft::test
