#pragma once
// The rough surface of the rough-contact benchmarks: a rigid flat on a periodic self-affine
// surface (H = 0.8, rms slope 0.05, shortest wavelength 16 cells, roll-off at a quarter of the
// period, seed 2004), so that bench_rough_contact and bench_load_sweep press the same surface.
#include "core/grid.hpp"
#include "core/types.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace coatfft::bench {

inline constexpr double rough_rms_slope = 0.05;
inline constexpr int rough_short_cutoff_cells = 16;

/// The gap max(z) - z [m] of a rigid flat on the surface z of the square period `grid`.
inline Field rough_gap(const Grid& grid) {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_slope = rough_rms_slope;
  spec.short_cutoff = rough_short_cutoff_cells * grid.dx();
  spec.long_cutoff = grid.lx() / 4;
  spec.seed = 2004;
  const Field z = self_affine_surface(grid, spec);
  return z.maxCoeff() - z;
}

}  // namespace coatfft::bench
