#pragma once
// Partial slip: a normal contact under a tangential load below full sliding, Coulomb's law cell by
// cell (docs/contact.md, "Partial slip"; docs/theory.md 6.5 for the Hertz contact's closed form).
//
// The indenter is pressed (the normal problem of contact_solver.hpp) and moved along +x by the
// shift delta; it is held in y. On every contact cell the body's surface either sticks to the
// indenter -- its slip over the step, s = u_t - u_t(previous step) - (delta - delta_prev) e_x,
// is zero -- or slips with the traction at the friction limit against its slip:
//   |q| <= mu p  everywhere,   s = 0 where |q| < mu p,   s = -|s| q/(mu p) where |q| = mu p,
// with u_t the in-plane displacement of the body's surface relative to the indenter's
// (surface_response.hpp). Under load control sum q_x dx dy = Q and delta is found; under shift
// control delta is given. At a held pressure a shift-controlled step is a convex problem in q
// (minimise 1/2 q.Kq - q.b over the disks |q| <= mu p), solved by a conjugate gradient in the
// manner of Polonsky & Keer (1999) whose slipping cells turn on their circles; under load control
// the shift that carries Q is found by a bracketing secant over such solves (docs/contact.md,
// "Partial slip"). On a body where q displaces the surface normally (a coated or compressible one
// against another material, docs/theory.md 2.9), the normal problem is solved again
// with that displacement in the gap and the tangential one with the new pressure, until the
// pressure settles (the fixed point of sliding_contact.hpp).
//
// A path of tangential loads (fretting) is solved step by step in the order given, each step from
// the state the one before left: friction depends on the history.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contact_solver.hpp"
#include "surface_response.hpp"

namespace coatfft {

/// A mask of cells: 1 where the contact sticks, 0 elsewhere.
using StickMask = Eigen::Array<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic>;

/// What the tangential problem prescribes: the load Q [N] along x, or the shift delta [m].
enum class TangentialControl { load, shift };

struct PartialSlipOptions {
  double friction = 0.0;         ///< mu > 0 (finite)
  double tolerance = 1e-8;       ///< the tangential iteration's relative traction change, > 0
  int max_iterations = 2000;     ///< iterations per shift-controlled solve (>= 1)
  int max_coupling_solves = 30;  ///< normal solves per step at most (>= 1)
  /// Called, when set, after each tangential iteration with its number and residual.
  std::function<void(int iteration, double residual)> on_iteration{};
};

/// The state a step leaves and the next one starts from.
struct PartialSlipState {
  Field pressure;                ///< p [Pa]
  Field qx, qy;                  ///< the tractions the body's surface receives [Pa]
  Field ux, uy;                  ///< the relative in-plane displacement of the surface [m]
  double shift = 0;              ///< delta [m]
  double dissipated_energy = 0;  ///< the friction work so far [J]
};

/// The conditions a partial-slip solution must meet on every cell (docs/contact.md, "Partial
/// slip"): their largest violations and whether each is within its bound.
struct CoulombCheck {
  double excess = 0;      ///< max (|q| - mu p) / max(mu p), > 0 where the disk is left
  double slip_error = 0;  ///< max |s + |s| q/(mu p)| over contact cells [m]
  double slip_bound = 0;  ///< the bound of slip_error [m]
  double slip_scale = 0;  ///< the step's largest in-plane move [m], the scale of the bound
  double outside = 0;     ///< max |q| off the contact [Pa]
  double load_error = 0;  ///< |sum q_x dA - Q| / (mu P) under load control, else 0
  bool holds = false;     ///< every condition within its bound
};

struct PartialSlipResult {
  ContactResult normal;         ///< the normal contact (its displacement includes q's share)
  Field qx, qy;                 ///< [Pa]
  Field slip_x, slip_y;         ///< the slip of this step [m]
  StickMask stick;              ///< 1 where a contact cell does not slip (CoulombCheck)
  double tangential_load = 0;   ///< sum q_x dx dy [N]
  double lateral_load = 0;      ///< sum q_y dx dy [N] (the indenter is held in y)
  double tangential_shift = 0;  ///< delta [m]
  double stick_area = 0, slip_area = 0;  ///< [m^2]
  double max_shear = 0;                  ///< max |q| [Pa]
  double step_energy = 0;                ///< friction work of this step, sum |q| |s| dx dy [J]
  double dissipated_energy = 0;          ///< the friction work so far [J]
  int iterations = 0;       ///< tangential iterations of the step (all coupling rounds)
  int coupling_solves = 0;  ///< normal solves of the step
  /// All applications: the normal solves' and the tangential response's (each 3 x 3 apply of
  /// a body or an elastic indenter counted once).
  int operator_applications = 0;
  CoulombCheck check;
  bool converged = false;  ///< the normal solves converged, the coupling settled, check.holds
  std::string warning;     ///< why not, when not
  PartialSlipState state;  ///< where the next step starts
};

/// The state before any tangential load: the normal contact solved without friction, q = 0, and
/// the in-plane displacement of its pressure.
PartialSlipState rest_state(RelativeSurfaceResponse& response, const ContactResult& normal);

/// One step from `previous` (rest_state for the first): the contact of `height` under the normal
/// `control` = `value` (as ContactSolver::solve) and the tangential `tangential` = `target` (Q
/// [N] with |Q| < mu P, or delta [m]). InvalidArgument for bad options or a load out of reach.
PartialSlipResult solve_partial_slip(ContactSolver& solver, RelativeSurfaceResponse& response,
                                     const Field& height, ContactControl control, double value,
                                     TangentialControl tangential, double target,
                                     const PartialSlipOptions& options,
                                     const PartialSlipState& previous);

/// A path: the steps of `targets` in the order given, the first from rest (one frictionless
/// normal solve first), each next from the one before. Every step's result, in order.
/// `on_step`, when set, is called before each step with its index.
std::vector<PartialSlipResult> solve_partial_slip_path(
    ContactSolver& solver, RelativeSurfaceResponse& response, const Field& height,
    ContactControl control, double value, TangentialControl tangential,
    const std::vector<double>& targets, const PartialSlipOptions& options,
    const std::function<void(std::size_t step)>& on_step = {});

/// A contact cell sticks unless it is at the friction limit and slips, both measurably: |q| >=
/// mu p (1 - stick_threshold) and |s| > stick_threshold times the step's largest move. Cells at
/// the verge -- at the limit to the tolerance, not slipping beyond the displacement's accuracy --
/// count as sticking: on a coupled body they can form a band where the tolerance's last digits
/// would otherwise decide (docs/contact.md, "Partial slip").
inline constexpr double stick_threshold = 1e-6;

/// The conditions of a partial-slip solution (CoulombCheck) with `tolerance` as the relative
/// bound: `bound` = mu p, s the slip, `load` the prescribed Q under load control.
CoulombCheck check_coulomb(const Grid& grid, const Field& bound, const Field& qx, const Field& qy,
                           const Field& sx, const Field& sy, std::optional<double> load,
                           double slip_scale, double tolerance);

}  // namespace coatfft
