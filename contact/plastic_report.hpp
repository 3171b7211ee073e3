#pragma once
// What a capped contact (ContactOptions::hardness) reports of its plastic part: the cells at the
// hardness, the depth the surface keeps, and the surface the depth leaves at zero load
// (docs/contact.md, "Hardness").
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "contact_solver.hpp"

namespace coatfft {

/// The plastic part of a capped contact.
struct PlasticReport {
  /// The cells at the hardness, times dx dy [m^2]: where the surface flows at this load.
  double plastic_area = 0;
  /// plastic_area over the contact area [-] (0 without contact).
  double plastic_area_fraction = 0;
  /// The largest plastic depth [m] (ContactResult::plastic_depth: in a sweep, accumulated).
  double max_plastic_depth = 0;
  /// The sum of the plastic depth times dx dy [m^3]: the volume the surface lost.
  double plastic_volume = 0;
};

/// The report of `result`, solved with ContactOptions::hardness = `hardness` on `grid`. Throws
/// InvalidArgument when the result has no plastic depth (solved without a hardness).
PlasticReport plastic_report(const ContactResult& result, double hardness, const Grid& grid);

/// The gap the permanent surface leaves at zero load: height + plastic_depth less its minimum
/// (the indenter just touching the dented surface) [m]; both of one shape.
Field residual_gap(const Field& height, const Field& plastic_depth);

}  // namespace coatfft
