#pragma once
// The tangential problem of a partial-slip step at a held pressure (contact/partial_slip.hpp): the
// tractions q on the disks |q| <= mu p that make the sticking cells follow the indenter, by a
// conjugate gradient on the free components with the iterate projected on the feasible set.
#include <functional>

#include "../../core/types.hpp"
#include "../partial_slip.hpp"
#include "../surface_response.hpp"

namespace coatfft::detail {

struct TangentialProblem {
  const Field* pressure;      ///< p [Pa], held
  const Field* bound;         ///< mu p [Pa]
  const Field* target_x;      ///< where a sticking cell's u_x stays: the previous step's [m]
  const Field* target_y;      ///< likewise u_y [m]
  TangentialControl control;  ///< load: `value` is Q [N]; shift: the shift's increment [m]
  double value;
};

struct TangentialSolution {
  Field qx, qy;                ///< [Pa]
  Field ux, uy;                ///< the relative in-plane displacement under p and q [m]
  Field sx, sy;                ///< the slip of the step [m]
  double shift_increment = 0;  ///< delta - delta_prev [m]
  double residual = 0;         ///< the last relative change of q
  int iterations = 0;
  int applications = 0;  ///< 3 x 3 applications (an elastic indenter's counted too)
  CoulombCheck check;
};

struct TangentialSettings {
  double tolerance;    ///< relative traction change, and the Coulomb check's bound
  int max_iterations;  ///< per shift-controlled solve
  std::function<void(int, double)> on_iteration;
};

/// Solves the shift-controlled `problem` from the tractions (qx, qy) (projected on the disks
/// first) until the relative change of q is below the tolerance and the Coulomb check holds.
TangentialSolution solve_tangential(RelativeSurfaceResponse& response,
                                    const TangentialProblem& problem, Field qx, Field qy,
                                    const TangentialSettings& settings);

/// Solves the load-controlled `problem` (|Q| < mu P): shift-controlled solves, each from the
/// last one's tractions, at the shifts of a bracketing secant, the first at the shift increment
/// `guess`, until the load is carried to the tolerance times mu P. Iterations and applications
/// are the sums over the solves.
TangentialSolution solve_tangential_load(RelativeSurfaceResponse& response,
                                         const TangentialProblem& problem, Field qx, Field qy,
                                         double guess, const TangentialSettings& settings);

}  // namespace coatfft::detail
