#pragma once
// The limits of an analytic disk load (Hertz or uniform) that every front end applies to what a
// user types, so that the program and the Python module refuse the same loads with the same
// reasons. The generators themselves (hertz_pressure, uniform_disk_pressure) accept any finite
// amplitude and positive radius: a library caller may want a sub-cell or a negative load.
#include <string_view>

#include "../core/grid.hpp"
#include "sampling.hpp"

namespace coatfft {

/// The names a front end gives a disk load's inputs in its messages.
struct DiskLoadKeys {
  std::string_view amplitude;  ///< "[pressure] p0", "hertz_pressure: p0"
  std::string_view radius;     ///< "[pressure] a"
  std::string_view grid;       ///< what sets the cells: "[grid] lx, ly, nx, ny", "grid"
};

/// Throws InvalidArgument, naming the keys of `keys`, unless the amplitude [Pa] is
/// finite and > 0, the radius [m] passes require_load_radius (finite, > 0, at most half the
/// domain) and, sampled at the cell centres, the disk is at least a cell wide: narrower, it either
/// misses every centre (no load) or fills a whole cell (a force far above the intended one), and
/// either way the output looks plausible. Cell averages keep the force, so they stay allowed.
void require_disk_load(const Grid& grid, double amplitude, double radius, Sampling sampling,
                       const DiskLoadKeys& keys);

}  // namespace coatfft
