#pragma once
// The discrete complementarity conditions of a contact solution (docs/contact.md, "Convergence"):
// with g = h + u - delta the gap of every cell,
//   p >= 0,   g >= -eps,   p g = 0  (|g| <= eps where p > 0),
// where eps is the accuracy to which the solver knows the gap. The contact solver reports
// `converged` only when they hold on every cell.
#include "../core/types.hpp"

namespace coatfft {

/// The largest overlap of a gap field, max(0, max(-g)) [m]: 0 when no cell interpenetrates.
double max_penetration(const Field& gap);

namespace detail {

/// eps [m] of the complementarity conditions for a solve stopped at a relative pressure change of
/// `tolerance`: tolerance * u_max (a relative pressure error of the tolerance moves a displacement
/// of u_max by about that much), plus 64 ulps of the gap's largest term `largest_term` (h, u and
/// the approach are added and subtracted cell by cell, so g carries their rounding).
double gap_tolerance(double tolerance, double u_max, double largest_term);

}  // namespace detail

}  // namespace coatfft
