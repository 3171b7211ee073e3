#pragma once
// Adhesive normal contact with a Dugdale cohesive zone (Maugis 1992), discretised cell by cell, on
// any SurfaceOperator (docs/contact.md, "Adhesion"): with g = h + u - delta the gap,
//   g = 0 and p >= -sigma0 on the contact,  p = -sigma0 where 0 < g < h0,  p = 0 where g >= h0,
// sigma0 = w / h0 the cohesive stress, w the work of adhesion and h0 the range. The attraction
// makes the problem non-convex; it is solved by an outer iteration on the cohesive set I (the
// cells with g < h0): for a fixed I the tension -sigma0 on I is a known load, and the rest,
// q = p + sigma0 >= 0 on I, solves an ordinary contact with the heights h - sigma0 K chi_I
// (ContactSolver, warm-started); I is then taken again from the new gap, until it holds.
#include <string>
#include <vector>

#include "../core/types.hpp"
#include "contact_solver.hpp"

namespace coatfft {

/// The Dugdale law and the outer iteration's limit.
struct AdhesionOptions {
  double work_of_adhesion = 0.0;  ///< w [J/m^2], finite and > 0
  double range = 0.0;             ///< h0 [m], finite and > 0
  /// Rounds of the outer iteration on the cohesive set (each one contact solve, warm-started);
  /// reaching it leaves the result not converged.
  int max_rounds = 200;
  /// The cohesive stress sigma0 = w / h0 [Pa].
  double strength() const { return work_of_adhesion / range; }
};

/// One adhesive solve. `contact` holds the net pressure p [Pa] (tensile negative, >= -sigma0),
/// the displacement, the gap, the net load (negative when tensile) and the approach (under load
/// control when the solver computes it), its iterations and applications those of all rounds.
struct AdhesiveResult {
  ContactResult contact;
  /// The cells at zero gap that press (p > -sigma0), times dx dy [m^2].
  double contact_area = 0.0;
  /// The cells off contact under the cohesive stress (0 < g < h0), times dx dy [m^2].
  double cohesive_area = 0.0;
  int rounds = 0;  ///< outer rounds
  /// Every inner solve converged, the cohesive set held, and check_dugdale passed on every cell.
  bool converged = false;
  /// From a previous state (a path's step): that state was in contact and this one is not (the
  /// contact jumped off: the branch it followed ended).
  bool jumped_off = false;
  /// The largest violation of the Dugdale conditions [m] (check_dugdale) and its bound.
  double violation = 0.0, violation_bound = 0.0;
  /// Why it did not converge, for people; empty when it did.
  std::string warning;
  /// The state a next solve starts from: 1 on the cohesive set (contact included), 0 elsewhere,
  /// and q = p + sigma0 on it.
  Field interaction, compressive;
};

/// One adhesive solve under load (total net force [N], which may be negative) or approach (rigid
/// approach [m] from h = 0, which may be zero or negative) control, from `previous` when given (a
/// path's state: the branch it follows) or from the cells within h0 of the indenter's first
/// touch. Throws InvalidArgument for a bad law (w or h0 not finite and > 0). Under load control a
/// load the cohesive set cannot hold (past pull-off) ends not converged, with a warning.
AdhesiveResult solve_adhesive(ContactSolver& solver, const Field& height, ContactControl control,
                              double value, const AdhesionOptions& options,
                              const AdhesiveResult* previous = nullptr);

/// solve_adhesive at each value in the order given, each from the state before it (loading and
/// unloading branches, the hysteresis of adhesion); `jumped_off` marks a step whose contact
/// ended.
std::vector<AdhesiveResult> solve_adhesive_path(ContactSolver& solver, const Field& height,
                                                ContactControl control,
                                                const std::vector<double>& values,
                                                const AdhesionOptions& options);

/// The Dugdale conditions on every cell of `result` (its pressure, gap and interaction set) for
/// the law `options`: on the cohesive set p >= -sigma0 and 0 <= g < h0, p > -sigma0 only where
/// g = 0; off it p = 0 and g >= h0. Returns the largest violation [m] of a gap condition (0 when
/// none; a pressure off its law counts as h0), which solve_adhesive holds to the gap's accuracy.
double dugdale_violation(const AdhesiveResult& result, const AdhesionOptions& options);

}  // namespace coatfft
