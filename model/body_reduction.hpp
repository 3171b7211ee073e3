#pragma once
// Reduced models of a layered body: where a coating's effect on the surface displacement is
// below the tolerance, the displacement is computed for a simpler body (docs/auto.md, section 2):
//
//   substrate       every coating far thinner than the load is felt through (the substrate alone);
//   top_half_space  the top coating so thick that the loaded region does not reach below it;
//   merged          adjacent layers elastically equal (or nearly) to the medium below them
//                   become one layer, and a coating equal to the substrate joins it.
//
// The effect of a reduction is bounded in Fourier space, for an axisymmetric reference load p of
// transform P(k), by
//
//   max_x |u_reduced - u_full| / u_full(0) <= \int |H_red - H_full| |P| k dk / \int H_full P k dk,
//
// (u(0) = (1/2 pi) \int H P k dk, and |J0| <= 1): a bound on the whole surface, for the
// continuous load. A reduction is used only where this bound is within the budget. For a coating
// far thinner than the loads, a closed-form bound of the substrate's effect decides instead
// (substrate_effect_bound), with no quadrature.
#include <limits>
#include <string>
#include <vector>

#include "../frf/frf.hpp"
#include "../layers/layer_stack.hpp"
#include "../loads/axisymmetric_load.hpp"

namespace coatfft {

/// An axisymmetric load standing for the scene's load in the effect bound: its shape and radius
/// (the amplitude cancels). Its transform is axisymmetric_load_transform.
struct ReferenceLoad {
  AxisymmetricLoad shape = AxisymmetricLoad::hertz;
  double radius = 0.0;  ///< [m], > 0
};

/// The bound above for replacing the body of FRF `full` by that of `reduced` under `load`
/// (relative to the full body's displacement at the load's centre). The integral runs to
/// k a = 1e8, and beyond it an analytic bound of the tail is added, so the value is an upper
/// bound to the quadrature's accuracy (1e-4 relative), times a margin of 1.5 for the scene's
/// load not being the reference load (docs/auto.md, section 2).
/// With `stop_above` finite, the integration stops as soon as the bound exceeds it (its
/// integrand is >= 0) and that partial value, a lower bound of the bound, is returned: enough to
/// refuse a reduction, at a fraction of the cost.
double reduction_effect(const Frf& full, const Frf& reduced, const ReferenceLoad& load,
                        double stop_above = std::numeric_limits<double>::infinity());

/// Closed-form upper bound of reduction_effect for the substrate reduction of `stack` (every
/// coating removed) under `load`, from FRF evaluations alone, no quadrature (docs/auto.md,
/// section 2, "Closed-form bound"): |k H - k H_sub| sampled at four wavenumbers an octave and
/// taken at the larger end of each bin, |P| by its envelope, and u(0) bounded below by the
/// substrate's closed form less the same integral. At most 4001 FRF evaluations (`evaluations`
/// counts them when given). +inf where the bound does not bound u(0) away from 0 (a coating that
/// is not thin against the load). A homogeneous `stack` gives 0.
double substrate_effect_bound(const LayerStack& stack, const ReferenceLoad& load,
                              long* evaluations = nullptr);

/// The most work reduce_body gives the accurate bound's Hankel references (reduction_effect's
/// denominator): the sum over the loads of (number of coatings) x a / h_top. A reference takes
/// about 10 a / h_top quadrature panels of 21 FRF evaluations, each costing about in proportion
/// to the number of coatings; beyond this limit the coating is far thinner than the loads
/// resolve and the closed-form bound decides (docs/auto.md, section 2, "Work").
inline constexpr double accurate_work_limit = 2e4;

/// The work of reduce_body, counted (docs/auto.md, section 2, "Work").
struct ReductionWork {
  long frf_evaluations = 0;  ///< of the given body's FRF and of every reduced body's
  int quadratures = 0;       ///< integrals by quadrature: Hankel references and effect bounds
};

struct BodyReduction {
  LayerStack body;              ///< the body to compute with: the given one where not reduced
  std::string kind = "none";    ///< "none", "substrate", "top_half_space", "merged"
  double estimated_effect = 0;  ///< reduction_effect of `body` against the given body
  std::string why;              ///< one sentence, for reports
  /// The reductions tried with their effects, for reports; an effect above the budget is a lower
  /// bound (reduction_effect's stop_above).
  std::vector<std::pair<std::string, double>> tried;
  ReductionWork work;
};

/// The simplest body whose effect bound, the largest over `loads` (at least one), is within
/// `budget` (> 0): a homogeneous one (substrate or top_half_space, the smaller effect of the
/// admissible ones) before merged layers; otherwise `stack` itself. A homogeneous `stack` is
/// returned as it is. Where the Hankel references would exceed accurate_work_limit, the
/// substrate is taken on substrate_effect_bound alone when that is within the budget (no
/// quadrature at all); otherwise the effects are bounded against that bound's lower bound of
/// u(0) instead of the Hankel reference. Either way the work is bounded (docs/auto.md, section 2,
/// "Work").
BodyReduction reduce_body(const LayerStack& stack, const std::vector<ReferenceLoad>& loads,
                          double budget);

}  // namespace coatfft
