#pragma once
// The contact solver's start (docs/contact.md, "Operator applications"). A start close to the
// solution spares the iterations in which the contact set still changes, and each of those costs
// a second operator application. Hertz's pressure on a paraboloid h = r^2/(2R) pressed to the
// approach delta is p0 sqrt(1 - r^2/a^2) = c sqrt(level - h) on {h < level}, level = delta/2:
// the start is that profile on any separation (on a rough surface, a Hertzian cap on each summit
// below the level), with the level
//   - under approach control: half the overlap, level = min h + (delta - min h)/2, Hertz's;
//   - under load control: first the level below which kTrialContactShare of the cells lie, then
//     corrected once from the displacement of that trial pressure (level_correction).
#include "../../core/types.hpp"

namespace coatfft::detail {

/// Share of the cells under the trial level of a load-controlled start.
inline constexpr double kTrialContactShare = 0.25;

/// sqrt(max(level - h, 0)) cell by cell [sqrt(m)]: the shape of the start, to be scaled.
Field hertzian_profile(const Field& h, double level);

class SolverRanks;

/// The value of h below which the share `share` (in [0, 1)) of the cells lie [m]: the k-th
/// smallest, k = share * cells. With `ranks`, of the field distributed over them (the same value).
double level_below(const Field& h, double share, const SolverRanks* ranks = nullptr);

/// The factor that corrects the level of a load-controlled start from the displacement `u` of
/// its trial pressure `p` (the profile at that level, scaled to the load). In contact, h + u is
/// constant, so u falls along h with slope -1; the trial's slope is -B, B the least-squares slope
/// of u against h over the support of p. For Hertz, a trial radius a' gives B = (a/a')^3 and the
/// level scales as a^2: the factor is B^(2/3) (1 when B is not finite and positive).
double level_correction(const Field& h, const Field& p, const Field& u,
                        const SolverRanks* ranks = nullptr);

}  // namespace coatfft::detail
