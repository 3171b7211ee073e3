#pragma once
// The scaling of a load-controlled contact solve into the range of double precision
// (docs/contact.md, "Scaling"): contact/load_scaling.cpp.
#include "contact/contact_solver.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "convolution/operators/surface_operator.hpp"
#include "core/types.hpp"

namespace coatfft::detail {

/// The power of two s by which a load-controlled solve of `load` [N] on the heights `h` is
/// scaled, (h / s, load / s); 1 for every physical problem. Costs one application of `op` (added
/// to `applications`) only when s may differ from 1; refuses a load whose displacements and the
/// heights lie beyond 1e+-180 of each other (contact/load_scaling.cpp).
double load_scale(SurfaceOperator& op, const Field& h, double load, int& applications,
                  const SolverRanks* ranks);

/// The solution of the unscaled problem (load or approach `value`) from that of the one scaled by
/// `s` (load_scale); refused when it is not representable in double precision.
void unscale(ContactResult& result, double s, double value, const SolverRanks* ranks);

}  // namespace coatfft::detail
