#pragma once
// The screening of a plane's cells for the largest principal and Tresca stresses by the closed
// forms (principal_closed_form.hpp; docs/stress.md, "Summary maxima"), private: the summary's
// maxima (scene/scene_stress.cpp) give the few cells it leaves the iterative eigensolver.
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace coatfft::detail {

struct ClosedFormScreen {
  bool finite = true;          ///< every von Mises stress finite (so every component)
  double mises = -INFINITY;    ///< the largest von Mises stress [Pa] (von_mises' value)
  std::size_t mises_cell = 0;  ///< its first cell
  /// The cells that may hold the largest principal or Tresca stress, in order: those whose
  /// closed-form value plus its error bound reaches the largest value less its bound.
  std::vector<std::size_t> candidates;
};

/// Screens the cells 0 .. count - 1 of the six component arrays (xx, yy, zz, yz, xz, xy [Pa]),
/// writing each cell's von Mises stress to mises_out[k] when mises_out is given. In blocks that
/// stay in the first-level cache, the closed forms vectorised (closed_form_screen.cpp); a cell
/// beyond [1e-90, 1e90] Pa gets the scaled public functions.
ClosedFormScreen screen_cells(const std::array<const double*, 6>& components, std::size_t count,
                              double* mises_out);

}  // namespace coatfft::detail
