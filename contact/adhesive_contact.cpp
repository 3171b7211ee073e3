#include "contact/adhesive_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "contact/complementarity.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft {

namespace {

void check_law(const AdhesionOptions& o) {
  COATFFT_REQUIRE(std::isfinite(o.work_of_adhesion) && o.work_of_adhesion > 0,
                  "adhesion: work_of_adhesion = ", o.work_of_adhesion,
                  " J/m^2, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(o.range) && o.range > 0, "adhesion: adhesion_range = ", o.range,
                  " m, but it must be finite and > 0");
  COATFFT_REQUIRE(o.max_rounds >= 1, "adhesion: max_rounds = ", o.max_rounds,
                  ", but it must be >= 1");
}

// One round's contact: q >= 0 against the heights h' = h - sigma0 K chi_I (the cohesive set's
// tension a known load), its gap, and whether it converged. With no cell reaching the indenter
// under approach control there is no contact: q = 0 and the gap is h' - delta.
struct Round {
  Field q, uq, gap;
  std::optional<double> approach;
  bool converged = true;
  int iterations = 0, applications = 0;
  bool feasible = true;  // load control: the set can hold the load
};

Round contact_round(ContactSolver& solver, const Field& h_eff, ContactControl control, double value,
                    double tension_load, const Field* start) {
  Round r;
  const double target = control == ContactControl::load ? value + tension_load : value;
  const bool touches = control == ContactControl::load ? target > 0 : value > h_eff.minCoeff();
  if (!touches) {
    r.feasible = control == ContactControl::approach;
    r.q = Field::Zero(h_eff.rows(), h_eff.cols());
    r.uq = r.q;
    r.gap = h_eff - (control == ContactControl::approach ? value : h_eff.minCoeff());
    if (control == ContactControl::approach) r.approach = value;
    return r;
  }
  ContactResult c = start && (*start > 0).any() ? solver.solve_from(h_eff, control, target, *start)
                                                : solver.solve(h_eff, control, target);
  r.converged = c.converged;
  r.iterations = c.iterations;
  r.applications = c.operator_applications;
  r.approach = c.approach;
  r.q = std::move(c.pressure);
  r.uq = std::move(c.displacement);
  r.gap = std::move(c.gap);
  return r;
}

// The cells within h0 of the indenter: under approach control of the rigid gap h - delta, under
// load control of the first touch (h - min h).
Field first_interaction(const Field& h, ContactControl control, double value, double range) {
  const double level = control == ContactControl::approach ? value : h.minCoeff();
  return (h - level < range).cast<double>();
}

// Whether a border cell carries pressure or tension: the contact or its cohesive zone reaches the
// domain's edge (on a free surface; a periodic one has none).
bool on_border(const Field& p) {
  const auto nx = p.rows(), ny = p.cols();
  return (p.row(0) != 0).any() || (p.row(nx - 1) != 0).any() || (p.col(0) != 0).any() ||
         (p.col(ny - 1) != 0).any();
}

// The result of the last round: p = q - sigma0 chi_I, u = u_q - sigma0 K chi_I.
AdhesiveResult assemble(Round&& r, const Field& interaction, const Field& tension_u, double sigma0,
                        const Grid& grid) {
  AdhesiveResult out;
  const double cell = grid.dx() * grid.dy();
  ContactResult& c = out.contact;
  c.pressure = r.q - sigma0 * interaction;
  c.displacement = r.uq - sigma0 * tension_u;
  c.load = c.pressure.sum() * cell;
  c.approach = r.approach;
  const Field pressing = (r.q > 0).cast<double>();
  out.contact_area = pressing.sum() * cell;
  out.cohesive_area = ((interaction > 0) && (r.q <= 0)).cast<double>().sum() * cell;
  c.contact_area = out.contact_area;
  if (c.contact_area > 0) c.contact_radius = std::sqrt(c.contact_area / std::numbers::pi);
  c.max_pressure = c.pressure.maxCoeff();
  c.max_penetration = max_penetration(r.gap);
  c.gap = std::move(r.gap);
  out.compressive = std::move(r.q);
  out.interaction = interaction;
  return out;
}

}  // namespace

double dugdale_violation(const AdhesiveResult& r, const AdhesionOptions& o) {
  const double sigma0 = o.strength(), h0 = o.range;
  const Field& p = r.contact.pressure;
  const Field& g = r.contact.gap;
  double worst = 0.0;
  for (Eigen::Index k = 0; k < p.size(); ++k) {
    const double gk = g(k), pk = p(k);
    double v = 0.0;
    if (r.interaction(k) > 0) {
      v = std::max({0.0, gk - h0, -gk});
      // A cell that presses (p above the tension) must touch; none may pull harder than sigma0.
      if (pk > -sigma0) v = std::max(v, std::abs(gk));
      if (pk < -sigma0 * (1 + 1e-12)) v = std::max(v, h0);
    } else {
      v = std::max(0.0, h0 - gk);
      if (pk != 0.0) v = std::max(v, h0);
    }
    worst = std::max(worst, v);
  }
  return worst;
}

AdhesiveResult solve_adhesive(ContactSolver& solver, const Field& height, ContactControl control,
                              double value, const AdhesionOptions& options,
                              const AdhesiveResult* previous) {
  check_law(options);
  COATFFT_REQUIRE(std::isfinite(value),
                  "adhesion: ", control == ContactControl::load ? "load" : "approach", " = ", value,
                  ", but it must be finite");
  SurfaceOperator& op = solver.surface_operator();
  const Grid& grid = op.grid();
  const double sigma0 = options.strength(), h0 = options.range, cell = grid.dx() * grid.dy();
  Field interaction =
      previous ? previous->interaction : first_interaction(height, control, value, h0);
  const Field* start = previous ? &previous->compressive : nullptr;
  Field q_start;
  Round round;
  Field tension_u;
  int rounds = 0, iterations = 0, applications = 0;
  bool held = false;
  while (rounds < options.max_rounds) {
    ++rounds;
    check_interrupt();
    tension_u = op.apply(interaction);
    ++applications;
    const Field h_eff = height - sigma0 * tension_u;
    round = contact_round(solver, h_eff, control, value, sigma0 * interaction.sum() * cell, start);
    iterations += round.iterations;
    applications += round.applications;
    if (!round.feasible) break;
    Field next = (round.gap < h0).cast<double>();
    // A cell that presses is on the set whatever rounding left its gap at.
    next = (round.q > 0).select(1.0, next);
    held = (next == interaction).all();
    // The last round's set stays the one its displacement belongs to.
    if (held || rounds == options.max_rounds) break;
    interaction = std::move(next);
    q_start = round.q;
    start = &q_start;
  }
  const bool inner_converged = round.converged;
  const bool feasible = round.feasible;
  // The gap is h - sigma0 K chi_I + K q - delta, accurate to the inner solve's own bound (relative
  // to K q) plus the rounding of every term.
  const double uq_max = round.uq.abs().maxCoeff();
  const double largest =
      height.abs().maxCoeff() + uq_max + sigma0 * tension_u.abs().maxCoeff() + std::abs(value);
  const double bound = detail::gap_tolerance(solver.options().tolerance, uq_max, largest);
  AdhesiveResult out = assemble(std::move(round), interaction, tension_u, sigma0, grid);
  out.rounds = rounds;
  out.jumped_off = previous && previous->contact_area > 0 && out.contact_area == 0;
  out.contact.touches_boundary = !op.periodic() && on_border(out.contact.pressure);
  out.contact.iterations = iterations;
  out.contact.operator_applications = applications;
  out.violation_bound = bound;
  out.violation = dugdale_violation(out, options);
  out.converged = feasible && inner_converged && held && out.violation <= out.violation_bound;
  out.contact.converged = out.converged;
  out.contact.status = out.converged ? ContactStatus::converged : ContactStatus::iteration_limit;
  if (!feasible)
    out.warning = detail::concat("the load ", value,
                                 " N is more tensile than the contact holds (past pull-off): "
                                 "follow it under approach control");
  else if (!held)
    out.warning = detail::concat("the cohesive set did not settle in ", rounds, " rounds");
  else if (!inner_converged)
    out.warning = "a contact solve of the last round did not converge";
  else if (!out.converged)
    out.warning = detail::concat("the Dugdale conditions fail by ", out.violation, " m (bound ",
                                 out.violation_bound, " m)");
  out.contact.warning = out.warning;
  return out;
}

std::vector<AdhesiveResult> solve_adhesive_path(ContactSolver& solver, const Field& height,
                                                ContactControl control,
                                                const std::vector<double>& values,
                                                const AdhesionOptions& options) {
  COATFFT_REQUIRE(!values.empty(), "adhesion: a path needs at least one value");
  std::vector<AdhesiveResult> path;
  for (const double value : values) {
    const AdhesiveResult* previous = path.empty() ? nullptr : &path.back();
    path.push_back(solve_adhesive(solver, height, control, value, options, previous));
  }
  return path;
}

}  // namespace coatfft
