#include "contact/detail/load_scaling.hpp"

#include <cmath>

#include "contact/detail/solver_ranks.hpp"
#include "core/error.hpp"

namespace coatfft::detail {

namespace {

// log2 of the displacement [m] a pressure of 1 Pa over the whole domain gives, estimated from
// one application: a unit pressure on one cell displaces by about dx / E*, a uniform one by the
// domain's width over E*, about that times the cells per side (an order of magnitude is enough).
double log2_compliance(SurfaceOperator& op, const SolverRanks* ranks) {
  const double cells_per_side = std::sqrt(static_cast<double>(op.grid().nb_cells()));
  const Field unit = op.unit_response();
  return std::log2(detail::extrema_over(ranks, unit.abs()).max) + std::log2(cells_per_side);
}

}  // namespace

// Load control solves (h / s, W / s) and returns s times its solution: K is linear, so that is
// the solution of (h, W). With P = W / A the mean pressure, H the heights' span, U = P C the
// displacement scale (C the compliance) and t ~ H / C the search direction, the iteration's inner
// products are of order P U, H t and P H; s^2 = P H divides them to U / H, H / U and 1 (docs/
// contact.md, "Scaling"), so a load of 1e150 N or 1e-150 N neither overflows nor underflows. s is
// a power of two (scaling is exact) and 1 while P H (P on a flat face) lies within 2^+-128 (about
// 1e+-38: every physical problem), so ordinary solves are untouched and cost no extra application;
// otherwise the compliance costs one (`applications`). U / H itself cannot be scaled away: beyond
// 2^+-600 (1e+-180) the problem is refused.
double load_scale(SurfaceOperator& op, const Field& h, double load, int& applications,
                  const SolverRanks* ranks) {
  const detail::RankExtrema h_range = detail::extrema_over(ranks, h);
  const double span = h_range.max - h_range.min;
  // In logarithms: W / A itself may overflow or underflow.
  const double log2_p = std::log2(load) - std::log2(op.grid().lx() * op.grid().ly());
  // A flat face (span 0) is judged by P alone: its heights enter no product.
  if (std::abs(log2_p + (span > 0 ? std::log2(span) : 0.0)) <= 128) return 1.0;
  ++applications;
  const double log2_u = log2_p + log2_compliance(op, ranks);
  const double log2_h = span > 0 ? std::log2(span) : log2_u;  // flat: only U matters
  COATFFT_REQUIRE(std::abs(log2_u - log2_h) <= 600, "ContactSolver: load = ", load,
                  " N displaces the surface by about ", std::exp2(log2_u),
                  " m against heights "
                  "spanning ",
                  span,
                  " m: a ratio beyond 1e+-180, which double precision cannot "
                  "solve; choose a load nearer the heights' scale");
  return std::ldexp(1.0, static_cast<int>(std::lround(0.5 * (log2_p + log2_h))));
}

// The solution of the unscaled problem (load or approach `value`) from that of the scaled one
// (load_scale); refused, never returned as NaN or Inf, when it is not representable in double
// precision.
void unscale(ContactResult& result, double s, double value, const SolverRanks* ranks) {
  if (s != 1.0) {
    result.pressure *= s;
    result.displacement *= s;
    result.gap *= s;
    result.load *= s;
    if (result.approach) *result.approach *= s;
    result.max_pressure *= s;
    result.max_penetration *= s;
    result.plastic_depth *= s;
  }
  COATFFT_REQUIRE(
      std::isfinite(result.load) && std::isfinite(result.max_pressure) &&
          detail::all_over(ranks, result.displacement.allFinite() && result.gap.allFinite()),
      "ContactSolver: ", result.control == ContactControl::load ? "load" : "approach", " = ", value,
      ": the contact's pressure, displacement or gap leaves double precision; "
      "rescale the units of the load, the heights and the moduli");
}

}  // namespace coatfft::detail
