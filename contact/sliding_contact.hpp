#pragma once
// A normal contact under full sliding friction: q_x = mu p on the body's surface (the indenter
// moves along +x and drags the surface with it). On a body whose materials are not
// incompressible, or on two dissimilar bodies, the tractions displace the surface normally too
// (the coupling C of docs/theory.md 2.9; Johnson 1985, section 7.2: of order beta mu), which
// changes the gap and so the pressure. The normal problem is then solved again with the
// tractions' normal displacement of the last pressure in the gap, a fixed-point iteration that
// contracts by about that factor per step, until the pressure changes by less than the tolerance.
#include <functional>
#include <memory>

#include "../convolution/operators/cerruti_operator.hpp"
#include "contact_solver.hpp"

namespace coatfft {

/// The relative normal displacement [m] (into the body) that the traction field q_x [Pa] causes:
/// u_z of the body's surface, less the indenter's when it is elastic.
using TangentialCoupling = std::function<Field(const Field& qx)>;

/// The coupling of a body's 3 x 3 surface response `on_body` (its u_z under q_x), less an
/// elastic indenter's `on_indenter` (null: a rigid indenter), whose surface receives -q_x. Both
/// operators are shared with the caller, which may apply them for the in-plane displacements.
TangentialCoupling traction_coupling(std::shared_ptr<CerrutiOperator> on_body,
                                     std::shared_ptr<CerrutiOperator> on_indenter = nullptr);

struct SlidingOptions {
  double friction = 0.0;    ///< mu >= 0 (finite): q_x = mu p
  double tolerance = 1e-9;  ///< largest change of p between two solves over max p, > 0
  int max_iterations = 30;  ///< normal solves at most (>= 1)
  /// Called, when set, before each normal solve with its number (1, 2, ...), so that a caller's
  /// progress can say which solve the iterations are of.
  std::function<void(int solve)> on_solve{};
};

struct SlidingReport {
  int solves = 0;                ///< normal solves done (1: friction 0)
  double pressure_change = 0.0;  ///< last change of p between two solves over max p
  /// The coupling's effect: max |p - p_frictionless| over max p_frictionless. It depends on the
  /// grid: the largest change sits at the moving rim of the contact, where p ~ sqrt(a - r).
  double pressure_shift = 0.0;
  /// The shift of the pressure's centroid along x [m] against the frictionless solve (negative:
  /// towards the trailing side). An integral of p: independent of the grid to its accuracy.
  double centroid_shift = 0.0;
  bool converged = false;  ///< pressure_change <= tolerance (and every solve converged)
};

/// Solves the contact of `height` under `control` = `value` (as ContactSolver::solve) with the
/// tractions' coupling iterated to its fixed point. The result's displacement and gap include
/// the tractions' normal displacement; its operator_applications counts those of all the solves
/// (its iterations, the last solve's). InvalidArgument on bad options.
ContactResult solve_sliding(ContactSolver& solver, const TangentialCoupling& coupling,
                            const Field& height, ContactControl control, double value,
                            const SlidingOptions& options, SlidingReport* report = nullptr);

}  // namespace coatfft
