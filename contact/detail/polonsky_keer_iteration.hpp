#pragma once
// The iteration of the contact solver (contact/contact_solver.hpp): its steps in
// contact/polonsky_keer_iteration.cpp, its starts in contact/polonsky_keer_start.cpp, the check
// of a stop in contact/polonsky_keer_convergence.cpp and its result in
// contact/polonsky_keer_result.cpp.
#include <cstddef>
#include <limits>
#include <optional>

#include "contact/contact_solver.hpp"
#include "contact/detail/cell_passes.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "convolution/operators/surface_operator.hpp"
#include "core/types.hpp"

namespace coatfft::detail {

// The constrained conjugate gradient of Polonsky & Keer (1999) on one problem: the iterate, its
// work fields, and one function per step of their iteration. The steps are fused loops over the
// cells (no temporaries): at large N the element-wise work would otherwise rival the FFT-based
// operator application of each iteration.
//
// One application per iteration (docs/contact.md, "Operator applications"): the step
// p <- p - tau t needs r = K t for its length, and by linearity the same r moves the displacement,
// u <- u - tau r, exactly, unless the projection changed a cell (pressure cut to zero, or added
// on an overlap); only then is u = K p recomputed, a second application. The iterates are Polonsky
// & Keer's, who recompute u at every iteration. A stale u (the correction K d deferred) was tried
// and steers the conjugate gradient badly: 1.8 times the iterations at 1024^2, none converging
// once the deferred share reaches the step's size. What keeps the recomputations few is the start
// (initial_pressure.hpp): close to the solution, the contact set settles in a few iterations.
class PolonskyKeerIteration {
 public:
  // `start`, when given, is the pressure to start from (a warm or nested start:
  // start_from_pressure).
  // `ranks`: those the fields are distributed over (their rows), or null.
  PolonskyKeerIteration(SurfaceOperator& op, detail::Preconditioner* preconditioner,
                        const SolverRanks* ranks, const Field& h, ContactControl control,
                        double value, const ContactOptions& options, std::optional<Field> start);

  // One iteration; the status once the iteration has ended, nothing while it goes on.
  std::optional<ContactStatus> iterate(double tolerance);
  std::optional<ContactStatus> step(double tolerance);  // iterate() without its timing

  // The relative pressure change of the last step (infinity before the first).
  double residual() const { return residual_; }

  // Where the iterations' time went so far (steps, recomputations, preconditioner, passes).
  ContactTimings& timings() { return timings_; }

  // The result for the current iterate (one more operator application when its displacement is
  // not exact).
  ContactResult result(ContactStatus status, int iterations, bool compute_approach);

 private:
  struct WorkingSet {
    std::ptrdiff_t cells;  // I_c, widened by the overlaps after a stop that left some
    double norm;           // sum of g^2 over it
  };

  void start(bool warm);  // warm: p_ holds the pressure to start from
  void start_under_cap();
  void start_from_pressure();
  void start_uniform();
  void start_hertzian();
  bool scale_to_approach();
  void recompute_displacement();
  std::ptrdiff_t update_gap();
  WorkingSet select_working_set();
  bool complementary(double tolerance);
  void update_direction(std::ptrdiff_t n_working);
  // update_direction's sums over the working set: of z, g, g_prev and t, and z.g and z.g_prev.
  struct DirectionSums {
    double z = 0.0, g = 0.0, q = 0.0, t = 0.0, g_dot_z = 0.0, q_dot_z = 0.0;
    DirectionSums& operator+=(const DirectionSums& o) {
      z += o.z;
      g += o.g;
      q += o.q;
      t += o.t;
      g_dot_z += o.g_dot_z;
      q_dot_z += o.q_dot_z;
      return *this;
    }
  };
  DirectionSums direction_sums();
  void write_direction(double z_mean, double beta, double t_mean);
  std::optional<double> step_length(std::ptrdiff_t n_working);
  struct Projected {
    double p_sum;   // sum of the projected pressure, before the load's scaling
    double change;  // sum |p - p_old| of it
    // Under a cap: the sum and the largest of the cells below it, and the cells at it.
    double free_sum = 0.0, free_max = 0.0;
    std::ptrdiff_t at_cap = 0;
  };
  Projected project(double tau);
  double enforce_load(Projected projected);
  // The hardness's part of a load-controlled step (contact/polonsky_keer_cap.cpp).
  struct CapLoad {
    double load = 0.0;   // sum of min(cap, s p) over the cells, in pressure units
    double slope = 0.0;  // its derivative in s: the sum of p over the cells below the cap
    CapLoad& operator+=(const CapLoad& o) {
      load += o.load;
      slope += o.slope;
      return *this;
    }
  };
  CapLoad capped_load(double s);
  Projected cap_sums();
  std::optional<double> cap_scale(const Projected& sums);
  double restore_load_under_cap(Projected projected);
  double rescale_under_cap(double s, const double* previous);
  void scale_all_below_cap(double s);

  SurfaceOperator& op_;
  detail::Preconditioner* preconditioner_;  // null: the classic, unpreconditioned iteration
  const SolverRanks* ranks_;  // null: the fields are whole; otherwise every sum is over the ranks
  const Field& h_;
  ContactControl control_;
  bool load_control_;
  double value_;  // the prescribed load [N] or approach [m]
  double delta_;  // approach control: the fixed approach; load control: 0 (g's mean is removed)
  // Load control: the approach, mean of h + u over I_c (update_gap). g_ holds h + u - delta; the
  // gap proper, g_ - g_mean_, is formed where it is read (a pass fewer than removing the mean).
  double g_mean_ = 0.0;
  double cell_area_;
  std::ptrdiff_t n_cells_;
  int workers_;  // threads of the element-wise passes (one below kParallelCells)
  // p_ is held unscaled: the pressure is scale_ p_. The load's scaling (enforce_load) is applied
  // by the next projection, which writes p anyway: a pass fewer than scaling it in place. g_
  // holds the gap h + K p - delta, moved by linearity (project); its scale follows in update_gap
  // (gap_scale_: g_ is the gap of gap_scale_ p_), or K p alone after a recomputation
  // (g_is_displacement_). The displacement is not held apart (a field less: docs/scale.md,
  // "Memory per cell") but under a cap (u_ and v_ below). r_ serves three fields whose lives do not
  // overlap (docs/scale.md, "Memory per cell"): the preconditioned gap z (from select_working_set
  // to write_direction), r = K t (step_length to project) and, after project() wrote the new
  // pressure into it and swapped it with p_, the previous pressure (old_scale_ its factor).
  Field p_, u_, g_, t_, r_;
  double scale_ = 1.0, old_scale_ = 1.0, gap_scale_ = 1.0;
  bool g_is_displacement_ = false;
  // Where a recomputation writes K p: g_ (then g_is_displacement_), or u_ under a cap.
  Field& displacement() { return capped_ ? u_ : g_; }
  // Two sets of cells in one byte a cell: the working set (kWorking; the passes over its cells
  // read it instead of p and g) and the set the direction t (and g_prev_) was last written on
  // (kDirectionSet; outside it both are zero).
  static constexpr unsigned char kWorking = 1, kDirectionSet = 2;
  ByteMask cell_sets_;
  // Polak-Ribiere: the previous gap on its working set (empty for Polonsky & Keer's rule). The
  // preconditioned gap z lives in r_ (g itself serves without a preconditioner). In single
  // precision (half a field's memory): it enters only beta's numerator z.(g - g_prev) and
  // Powell's test |z.g_prev| >= 0.2 z.g, where its rounding, 6e-8 of the gap, moves beta by as
  // little; the step, the projection and the stop stay in double.
  SingleField g_prev_;
  double g_dot_z_old_ = 1.0;
  Conjugation conjugation_;
  // Keep the previous direction: false before the first step and, under Polonsky & Keer's rule,
  // after a step that added contact cells.
  bool conjugate_ = false;
  double residual_ = std::numeric_limits<double>::infinity();
  // false: Polonsky & Keer's original (uniform start, u = K p recomputed at every iteration).
  bool update_by_linearity_;
  bool exact_ = false;  // u = K p (to rounding); false once the projection changed a cell
  // The next step works on I_c and the overlapping cells {p = 0, g < 0} (a steepest-descent
  // restart): set when the iteration stopped on I_c while cells outside it overlap.
  bool widen_ = false;
  int applications_ = 0;
  ContactTimings timings_;
  // The hardness (ContactOptions::hardness; infinity without one): p <= cap_ on every cell. The
  // displacement is then held, in two parts, u_ = K p on the cells below the cap and v_ = K p on
  // the cells at it (both empty without a cap, v_ during the start): a step moves only the first,
  // by linearity, and the load is restored by scaling only the first, so u_ stays exact until a
  // cell reaches or leaves the cap (plastic_exact_: v_ is exact).
  double cap_;
  bool capped_;
  Field v_;
  bool plastic_exact_ = true;
};

}  // namespace coatfft::detail
