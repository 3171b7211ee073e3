#pragma once
// Frictionless normal contact of a rigid indenter on an elastic body, on any SurfaceOperator:
// constrained conjugate gradient of Polonsky & Keer (1999), Wear 231, 206-219. See docs/contact.md.
//
// With h the initial separation (contact/indenter.hpp), u = K p the surface displacement and delta
// the rigid-body approach, the gap is g = h + u - delta and the solution satisfies
//   p >= 0,  g >= 0,  p g = 0   (complementarity), and either  sum p dx dy = W  (load control)
//   or delta given (approach control).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../convolution/fft/planning.hpp"
#include "../convolution/operators/surface_operator.hpp"
#include "../core/types.hpp"

namespace coatfft {

/// How the search direction carries the previous one (the conjugation's beta).
enum class Conjugation {
  /// Polonsky & Keer (1999): Fletcher-Reeves' beta = (g.z) / (g.z)_old, restarted (beta = 0)
  /// after every step that added contact cells.
  polonsky_keer,
  /// Polak-Ribiere's beta = max(0, z.(g - g_old)) / (g.z)_old (Gilbert & Nocedal 1992's
  /// non-negative form), not restarted for added cells: the difference g - g_old discounts what
  /// a change of the contact set did to the gap, so the direction keeps its memory while the set
  /// settles (Bugnicourt et al. 2018 drop the restart in the same spirit). Restarted instead by
  /// Powell's (1977) test, when |z.g_old| >= 0.2 z.g: without it the set could cycle on a stiff
  /// thin coating. Fewer iterations on rough surfaces (docs/contact.md, "Conjugation").
  polak_ribiere,
};

/// The multiplier of the preconditioner (contact/detail/fourier_preconditioner.hpp).
enum class PreconditionerSymbol {
  /// |k|: the inverse of the half-space symbol 2/(E* k) up to a constant, whatever the body.
  half_space,
  /// On a periodic operator, sqrt(|k| / K^) with K^ the operator's own symbol (one application,
  /// when the solver is built, reported by its first solve); |k| on free surfaces and distributed
  /// fields. On a coated body, whose k K^ varies by up to the ratio of the moduli, it needed 0.6
  /// to 0.8 times the iterations of |k| at ratios of 10 to 1000 on a smooth rough surface, and
  /// 0.8 to 1.1 times on one rough down to the grid's scale (docs/contact.md, "Preconditioning").
  operator_adapted,
};

/// Stopping rule and limits of the iteration.
struct ContactOptions {
  /// Converged when the relative pressure change of one iteration,
  /// sum |p_new - p_old| / sum p_new (Polonsky & Keer's criterion; held as an upper bound of it,
  /// docs/contact.md), drops below this and the complementarity conditions hold [-].
  double tolerance = 1e-10;
  /// Iteration limit; reaching it returns converged = false (never throws).
  int max_iterations = 1000;
  /// Load control only: also report the approach delta = mean over contact cells of (h + u).
  /// Off by default because delta needs the absolute displacement level, which a spectral
  /// (FRF-based) operator knows only up to its g(0) error; pressure, area and gap do not.
  bool compute_approach = false;
  /// Precondition the conjugate gradient with the inverse half-space symbol |k| (an FFT pair on
  /// the nx x ny grid per iteration; docs/contact.md). Keeps the iteration count nearly
  /// independent of N (24-33 for Hertz from 64^2 to 1024^2 from the uniform start, against
  /// 46-137 without). Off gives the classic Polonsky-Keer iteration.
  bool preconditioned = true;
  /// The preconditioner's multiplier (PreconditionerSymbol).
  PreconditionerSymbol preconditioner_symbol = PreconditionerSymbol::half_space;
  /// Threads (>= 1) of the preconditioner's FFTW transforms and, from 512^2 cells, of the
  /// iteration's element-wise passes (each chunk's sums added in chunk order: a result depends on
  /// the thread count only through rounding).
  int threads = 1;
  /// FFTW planning of the preconditioner's transforms; unset: FFTW_MEASURE from 2048^2 cells
  /// (applied once per iteration, measured plans repay their planning there; docs/contact.md,
  /// "Preconditioning"), FFTW_ESTIMATE below. The nested start's coarse solves use estimate.
  std::optional<Planning> preconditioner_planning;
  /// Move the displacement by linearity (u <- u - tau K t), recomputing u = K p only after a step
  /// that changed the contact set, from a Hertzian start (contact/detail/initial_pressure.hpp): one
  /// operator application per iteration, two in those that changed the set (docs/contact.md,
  /// "Operator applications"). Off gives Polonsky & Keer's original: their uniform start and
  /// u = K p recomputed at every iteration (two applications per iteration). Both solve the same
  /// problem to the same stopping rule.
  bool update_by_linearity = true;
  /// The conjugation of the search direction (Conjugation).
  Conjugation conjugation = Conjugation::polak_ribiere;
  /// Start a cold solve from the same contact solved on coarser grids (half the cells per side
  /// each, down to 64 cells, to a relative pressure change of 1e-3, each started the same way),
  /// its pressure carried to the fine grid cell by cell (docs/contact.md, "Nested start"), when the
  /// cells below the Hertzian start's trial level form more than one patch (a rough surface). Only
  /// where the operator offers its coarse form (SurfaceOperator::coarsened: periodic and DC-FFT
  /// operators on even grids); a warm start (solve_sweep) does not use it. Off: the start of
  /// update_by_linearity.
  bool nested_start = true;
  /// Called, when set, after every iteration that took a step (all but a breakdown), with the
  /// iteration's number (1, 2, ...) and the residual it left (the relative pressure change, as
  /// ContactResult::residual): a caller can show progress, since the solver itself never prints.
  /// It runs on the solving thread and costs one call per iteration; throttling is the caller's.
  std::function<void(int iteration, double residual)> on_iteration;
  /// Called, when set, before each solve of a sweep (ContactSolver::solve_sweep) with its index
  /// (0, 1, ...) in the sweep's ascending order, the number of values and the value, so that a
  /// caller's progress can say which value the iterations are of.
  std::function<void(std::size_t index, std::size_t count, double value)> on_value{};
  /// The hardness H [Pa] of the softer surface, when set: the pressure is capped, 0 <= p <= H on
  /// every cell, and the overlap of the cells at H is plastic depth (the elastic-perfectly-plastic
  /// surface of Tian & Bhushan 1996 and Almqvist et al. 2007; docs/contact.md, "Hardness"). The
  /// body below stays elastic. Unset: the elastic contact.
  std::optional<double> hardness{};
};

/// Which quantity the solve prescribes.
enum class ContactControl { load, approach };

/// How the iteration ended. Whether the contact reaches the domain edge is not a status but a
/// property of the returned iterate (ContactResult::touches_boundary): a truncated contact can end
/// in any of these.
enum class ContactStatus {
  /// The relative pressure change fell below the tolerance (or the gap was already exactly
  /// uniform on the contact set), and the complementarity conditions hold on every cell
  /// (contact/complementarity.hpp).
  converged,
  /// max_iterations done without converging; the last iterate is returned.
  iteration_limit,
  /// Breakdown: the projection on p >= 0 removed all pressure (or none was left to start from);
  /// the last iterate that carried pressure is returned.
  pressure_vanished,
  /// Breakdown: r.t <= 0 along the search direction, impossible for a positive-definite operator;
  /// the iterate before the failed step is returned.
  non_positive_curvature,
  /// A sliding contact (contact/sliding_contact.hpp): every normal solve converged, but the
  /// friction coupling's fixed-point iteration used up its normal solves first.
  coupling_limit,
};

/// The status as an identifier: "converged", "iteration_limit", "pressure_vanished",
/// "non_positive_curvature", "coupling_limit" (the value of summary.json's "status").
std::string_view to_string(ContactStatus status);

/// Where a solve's wall time went [s] (steady clock), for the benchmarks of the solver's cost
/// (docs/benchmarks.md, "Where a contact iteration goes"): the operator applications of the
/// steps (one an iteration), the recomputations of the displacement after a step changed the
/// contact set (and for the result), the preconditioner's transforms, the element-wise passes
/// over the fields (the rest of the iterations), and the start (scaling, initial pressure).
struct ContactTimings {
  double steps = 0, recomputations = 0, preconditioner = 0, passes = 0, start = 0;
  double total = 0;  ///< the whole solve
};

/// Output of one contact solve. Fields have the grid's shape (nx, ny).
struct ContactResult {
  Field pressure;      ///< p [Pa], >= 0 everywhere
  Field displacement;  ///< u = K p [m], positive into the body, as the operator returns it
  /// g = h + u - delta [m]: 0 (to solver accuracy) on contact cells, >= 0 elsewhere. Under load
  /// control delta is the mean over contact cells of (h + u), which makes the gap independent of
  /// a g(0) error; under approach control it is the given approach.
  Field gap;
  ContactControl control = ContactControl::load;
  double load = 0;  ///< total force W = sum p dx dy [N]
  /// Rigid-body approach delta [m]: the input under approach control; under load control present
  /// only when ContactOptions::compute_approach is set (it depends on the operator's g(0)).
  std::optional<double> approach;
  double contact_area = 0;  ///< A = (number of cells with p > 0) dx dy [m^2]
  /// Equivalent contact radius sqrt(A / pi) [m]; absent when there is no contact (A = 0).
  std::optional<double> contact_radius;
  double max_pressure = 0;  ///< max p [Pa]
  int iterations = 0;       ///< conjugate-gradient iterations done
  /// Operator applications the solve made (the dominant cost): one per iteration, plus the
  /// displacement's recomputations (ContactOptions::update_by_linearity).
  int operator_applications = 0;
  /// Applications on the coarser grids of a nested start (ContactOptions::nested_start), each
  /// on a quarter (or less) of the cells of a fine one; 0 without.
  int coarse_applications = 0;
  double residual = 0;  ///< last relative pressure change (see ContactOptions::tolerance)
  /// How the iteration ended; a result that no solve filled counts as not converged.
  ContactStatus status = ContactStatus::iteration_limit;
  bool converged = false;  ///< status == ContactStatus::converged
  /// True when a border cell carries pressure: the contact reaches the domain edge, so the
  /// domain is too small for the problem (the solution is that of a truncated body). Always false
  /// on a periodic operator, which has no edge.
  bool touches_boundary = false;
  /// The largest overlap max(0, -min g) [m] of the returned gap: 0 when no cell interpenetrates.
  /// A converged result has at most the gap's accuracy here (contact/complementarity.hpp).
  double max_penetration = 0;
  /// With ContactOptions::hardness: the plastic depth [m] of every cell, the overlap -g of the
  /// cells at the hardness (0 elsewhere), positive into the body; in a sweep with a hardness
  /// (ContactSolver::solve_sweep) the depth accumulated over its steps, the permanent change of
  /// the surface. Empty without a hardness.
  Field plastic_depth;
  /// Human-readable notes, describe(*this, tolerance): empty when all is well. For display only;
  /// programs read status and touches_boundary.
  std::string warning;
  ContactTimings timings;
};

/// The notes on a result for users, derived from its status, touches_boundary, iterations and
/// residual (tolerance: the one the solve ran with): a breakdown, then the domain edge, then the
/// iteration limit, joined by "; ". Empty for a converged solve inside the domain.
std::string describe(const ContactResult& result, double tolerance);

/// The order a sweep (ContactSolver::solve_sweep) solves `values` in: ascending, then with
/// `unload` the values below the largest, descending (the unloading branch).
std::vector<double> sweep_order(std::vector<double> values, bool unload);

/// Polonsky-Keer solver bound to one operator (the operator must outlive the solver). Each
/// iteration costs one operator application (plus one periodic FFT pair of the grid's size when
/// preconditioned) and, now and then, one more to recompute the displacement exactly
/// (ContactResult::operator_applications counts them all).
namespace detail {
class Preconditioner;
class SolverRanks;
}  // namespace detail

class ContactSolver {
 public:
  /// Throws InvalidArgument for tolerance not finite and > 0 or max_iterations < 1. Plans the
  /// preconditioner's FFTs (when enabled) once, for all solves.
  explicit ContactSolver(SurfaceOperator& op, ContactOptions options = {});
  /// On fields distributed over `ranks` (distributed/distributed_contact.hpp builds it): the
  /// heights, pressures, displacements and gaps are this rank's rows, the result's numbers are
  /// the whole grid's, and every solve is collective. The nested start is taken where the operator
  /// coarsens (a distributed periodic one whose ranks' rows pair up: docs/scale.md).
  ContactSolver(SurfaceOperator& op, ContactOptions options,
                std::shared_ptr<const detail::SolverRanks> ranks);
  ~ContactSolver();
  ContactSolver(const ContactSolver&) = delete;
  ContactSolver& operator=(const ContactSolver&) = delete;

  /// Load control: total force `load` [N] (finite, > 0) on the indenter of separation `height`
  /// [m] (Field of the operator's grid shape, finite). Pressure, area and gap do not depend on a
  /// constant (g(0)) error of the operator; only the optional approach does.
  ContactResult solve_load(const Field& height, double load);

  /// Approach control: rigid-body approach `approach` [m], finite and > min(height) (otherwise
  /// there is no contact). The load is an output.
  ContactResult solve_approach(const Field& height, double approach);

  /// Dispatches to solve_load or solve_approach.
  ///
  /// Each solve checks for interrupts before every iteration (core/interrupt.hpp) and throws
  /// Interrupted when asked to stop; the solver and its operator can then solve again.
  ContactResult solve(const Field& height, ContactControl control, double value);

  /// A sweep on one operator: the solves of `values` (each checked as solve checks it, all
  /// before the first solve) in ascending order, each started from the solutions before it
  /// (the first from the usual start, the second from the first's pressure, the others from the
  /// secant through the last two), scaled to its own value (one application). The results, one per
  /// value, in ascending order of value, each as solve would return it (its operator_applications
  /// its own). A neighbouring solution's contact set is close to the next one's; against solves
  /// started cold (nested on a rough surface) a sweep saves their coarse grids' applications
  /// (bench/bench_load_sweep.cpp).
  ///
  /// `unload`: after the ascending values, the values below the largest in descending order
  /// (the unloading branch; the results follow that order). With ContactOptions::hardness the
  /// sweep is a loading history: each step's plastic depth is carried to the next as a
  /// permanent change of the surface (the heights plus the depth so far), so the depth never
  /// decreases (docs/contact.md, "Hardness"). Without a hardness the unloading branch repeats
  /// the elastic solutions.
  std::vector<ContactResult> solve_sweep(const Field& height, ContactControl control,
                                         std::vector<double> values, bool unload = false);

  /// solve() from the pressure `start` (of the grid's shape, clipped at zero and scaled to the
  /// value: one application) instead of the usual start: for a solve whose neighbour is known (a
  /// path of solves, the rounds of an outer iteration). A start without pressure is the usual one.
  ContactResult solve_from(const Field& height, ContactControl control, double value, Field start);

  const ContactOptions& options() const { return options_; }
  /// The operator the solver is bound to.
  SurfaceOperator& surface_operator() const { return op_; }
  /// The grid of the operator the solver is bound to.
  const Grid& grid() const { return op_.grid(); }

 private:
  void check_value(ContactControl control, double value) const;
  // The height field against the operator's grid, and an approach against the heights.
  void check_problem(const Field& height, ContactControl control, double value) const;
  ContactResult run(const Field& height, ContactControl control, double value,
                    std::optional<Field> start);
  // A nested start: the pressure of the same contact solved on the coarser grid, on this grid
  // (none where the grid is too small, the surface one patch or the operator without a coarse
  // form), with the applications it cost on this grid (the coarse operator's) and on the coarser.
  struct NestedStart {
    std::optional<Field> pressure;
    int applications = 0;
    int coarse_applications = 0;
  };
  NestedStart nested_start(const Field& height, ContactControl control, double value);

  SurfaceOperator& op_;
  ContactOptions options_;
  std::shared_ptr<const detail::SolverRanks> ranks_;  // null: whole fields
  std::unique_ptr<detail::Preconditioner> preconditioner_;
  // The application that built the preconditioner's symbol, not yet reported by a solve.
  int pending_applications_ = 0;
};

}  // namespace coatfft
