#include "contact/contact_solver.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contact/complementarity.hpp"
#include "contact/contact_patches.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "contact/fourier_preconditioner.hpp"
#include "contact/grid_transfer.hpp"
#include "contact/initial_pressure.hpp"
#include "core/detail/huge_pages.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft {

namespace {

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;
using CellMask = Eigen::Array<unsigned char, Eigen::Dynamic, 1>;  // one byte a cell

// A work field of h's shape on huge pages (core/detail/huge_pages.hpp), its values unset, and
// the same zeroed; a cell mask of h's size, cleared.
Field work_field(const Field& h) {
  return detail::untouched_array<Field>(h.rows(), h.cols());
}
Field zero_field(const Field& h) {
  return detail::zeroed_array<Field>(h.rows(), h.cols());
}
CellMask clear_mask(const Field& h) {
  return detail::zeroed_array<CellMask>(h.size(), 1);
}

// The fewest cells whose element-wise passes run on ContactOptions::threads: a pass over 512^2
// cells takes about a millisecond, against tens of microseconds to start a thread.
constexpr std::ptrdiff_t kParallelCells = 512 * 512;

using detail::SolverRanks;

// Mean of f over the cells where mask is set, `count` of them over the ranks (> 0).
double masked_mean(const Field& f, const Mask& mask, std::ptrdiff_t count, const SolverRanks* r) {
  return detail::sum_over(r, mask.select(f, 0.0).sum()) / static_cast<double>(count);
}

// Whether a cell on the grid's border carries pressure; with ranks, p is this rank's rows, whose
// first and last are the grid's only on the first and last rank.
bool pressure_on_border(const Field& p, const SolverRanks* r, std::ptrdiff_t ny) {
  const auto nx = p.rows();
  const auto rows = p.cols();
  const bool first = r == nullptr || r->first_row() == 0;
  const bool last = r == nullptr || r->first_row() + r->rows() == ny;
  const bool mine =
      rows > 0 && ((p.row(0) > 0).any() || (p.row(nx - 1) > 0).any() ||
                   (first && (p.col(0) > 0).any()) || (last && (p.col(rows - 1) > 0).any()));
  return !detail::all_over(r, !mine);
}

void append(std::string& text, const std::string& more) {
  if (!text.empty()) text += "; ";
  text += more;
}

// Sums of a pass over the cells, added chunk by chunk (count and sum, or maxima, or nothing).
struct CountSum {
  std::ptrdiff_t count = 0;
  double sum = 0.0;
  CountSum& operator+=(const CountSum& o) {
    count += o.count;
    sum += o.sum;
    return *this;
  }
};
struct NoSums {
  NoSums& operator+=(const NoSums&) { return *this; }
};

// Runs pass(first, last, sums) on contiguous chunks of the n cells, one per worker, and adds the
// chunks' sums in chunk order (the same result for the same number of workers). The passes are
// bound by memory bandwidth, which a second core raises; with one worker the pass runs inline.
template <class Sums, class Pass>
Sums over_cells(std::ptrdiff_t n, int workers, const Pass& pass) {
  std::vector<Sums> parts(static_cast<std::size_t>(workers));
  detail::parallel_chunks(0, n, workers,
                          [&](std::ptrdiff_t w, std::ptrdiff_t first, std::ptrdiff_t last) {
                            pass(first, last, parts[static_cast<std::size_t>(w)]);
                          });
  Sums total{};
  for (const Sums& part : parts) total += part;
  return total;
}

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
  void start_from_pressure();
  void start_uniform();
  void start_hertzian();
  void scale_to_approach();
  void recompute_displacement();
  std::ptrdiff_t update_gap();
  WorkingSet select_working_set();
  bool complementary(double tolerance);
  void update_direction(std::ptrdiff_t n_working);
  std::optional<double> step_length(std::ptrdiff_t n_working);
  struct Projected {
    double p_sum;   // sum of the projected pressure, before the load's scaling
    double change;  // sum |p - p_old| of it
  };
  Projected project(double tau);
  double enforce_load(Projected projected);

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
  // p_ and u_ are held unscaled: the pressure is scale_ p_ and its displacement scale_ u_. The
  // load's scaling (enforce_load) is applied by the next projection, which writes both anyway:
  // a pass fewer than scaling them in place. project() writes the new pressure into p_old_'s
  // field and swaps the two (old_scale_ is the old pressure's factor).
  Field p_, u_, g_, t_, r_, p_old_;
  double scale_ = 1.0, old_scale_ = 1.0;
  // The working set, one byte a cell (the passes over its cells read it instead of p and g), and
  // the set the direction t (and g_prev_) was last written on: outside it both are zero.
  CellMask working_, direction_set_;
  // Polak-Ribiere: the previous gap on its working set (empty for Polonsky & Keer's rule). The
  // preconditioned gap z lives in the preconditioner's own field (g itself serves without one).
  Field g_prev_;
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
};

// Adds the wall time of its scope to `bucket` [s].
class ScopedTimer {
 public:
  explicit ScopedTimer(double& bucket)
      : bucket_(bucket), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { bucket_ += detail::seconds_since(start_); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& bucket_;
  std::chrono::steady_clock::time_point start_;
};

PolonskyKeerIteration::PolonskyKeerIteration(SurfaceOperator& op,
                                             detail::Preconditioner* preconditioner,
                                             const SolverRanks* ranks, const Field& h,
                                             ContactControl control, double value,
                                             const ContactOptions& options,
                                             std::optional<Field> start_pressure)
    : op_(op),
      preconditioner_(preconditioner),
      ranks_(ranks),
      h_(h),
      control_(control),
      load_control_(control == ContactControl::load),
      value_(value),
      delta_(load_control_ ? 0.0 : value),
      cell_area_(op.grid().dx() * op.grid().dy()),
      n_cells_(h.size()),
      workers_(n_cells_ >= kParallelCells ? options.threads : 1),
      p_(start_pressure ? std::move(*start_pressure) : work_field(h)),
      u_(work_field(h)),
      g_(work_field(h)),
      t_(zero_field(h)),  // read (times beta = 0) by the first iteration
      r_(work_field(h)),
      p_old_(work_field(h)),
      working_(clear_mask(h)),
      direction_set_(clear_mask(h)),
      conjugation_(options.conjugation),
      update_by_linearity_(options.update_by_linearity) {
  if (conjugation_ == Conjugation::polak_ribiere) g_prev_ = zero_field(h);
  start(start_pressure.has_value());
}

// The initial pressure.
void PolonskyKeerIteration::start(bool warm) {
  if (warm) {
    p_ = p_.max(0.0);
    if (detail::sum_over(ranks_, p_.sum()) > 0) {
      start_from_pressure();
      return;
    }
  }
  if (update_by_linearity_) {
    start_hertzian();
  } else {
    start_uniform();
  }
}

// A warm start (a sweep, ContactSolver::solve_sweep): p_ holds the pressure of a neighbouring
// solve, scaled here to this one's load or approach (one application). Its contact set is close
// to this one's, which is what the iteration spends its recomputations on.
void PolonskyKeerIteration::start_from_pressure() {
  if (!load_control_) {
    scale_to_approach();
    return;
  }
  p_ *= value_ / (detail::sum_over(ranks_, p_.sum()) * cell_area_);
  recompute_displacement();
}

// Polonsky & Keer's start: under load control the load spread uniformly over the whole domain;
// under approach control a uniform pressure on the geometric overlap {h < delta}, scaled to the
// approach (one application).
void PolonskyKeerIteration::start_uniform() {
  if (load_control_) {
    p_.setConstant(value_ /
                   (static_cast<double>(detail::count_over(ranks_, n_cells_)) * cell_area_));
    return;
  }
  p_ = (h_ < delta_).cast<double>();
  scale_to_approach();
}

// A Hertzian start (initial_pressure.hpp): sqrt(level - h) on {h < level}. Under approach control
// the level is half the overlap, Hertz's; under load control it is fitted by one application.
void PolonskyKeerIteration::start_hertzian() {
  const detail::RankExtrema h_range = detail::extrema_over(ranks_, h_);
  const double h_min = h_range.min;
  if (!load_control_) {
    p_ = detail::hertzian_profile(h_, h_min + 0.5 * (delta_ - h_min));
    scale_to_approach();
    return;
  }
  double level = detail::level_below(h_, detail::kTrialContactShare, ranks_) - h_min;
  if (!(level > 0)) {  // a flat face holds a quarter of the cells: a level just above it
    const double h_max = h_range.max;
    level = h_max > h_min ? detail::kTrialContactShare * (h_max - h_min) : 1.0;
  }
  const auto carry_load = [&] {
    p_ = detail::hertzian_profile(h_, h_min + level);
    // A load whose displacements lie below the rounding of min(h) fits a level that h_min + level
    // cannot resolve: no cell is left, and the load rests on the lowest cells.
    if (!(detail::sum_over(ranks_, p_.sum()) > 0)) p_ = (h_ == h_min).cast<double>();
    p_ *= value_ / (detail::sum_over(ranks_, p_.sum()) * cell_area_);
  };
  carry_load();
  recompute_displacement();
  level *= detail::level_correction(h_, p_, u_, ranks_);
  carry_load();
  exact_ = false;
}

// Approach control: p scaled so that the mean gap over its support vanishes (one application).
void PolonskyKeerIteration::scale_to_approach() {
  const Mask support = p_ > 0;
  const auto n_support = detail::count_over(ranks_, support.count());
  recompute_displacement();
  const double scale = masked_mean(delta_ - h_, support, n_support, ranks_) /
                       masked_mean(u_, support, n_support, ranks_);
  COATFFT_REQUIRE(std::isfinite(scale) && scale > 0, "ContactSolver: operator '", op_.name(),
                  "' returned a non-positive mean displacement under a positive pressure");
  p_ *= scale;
  u_ *= scale;
}

void PolonskyKeerIteration::recompute_displacement() {
  const ScopedTimer timer(timings_.recomputations);
  op_.apply(p_, u_);
  ++applications_;
  exact_ = true;
}

std::optional<ContactStatus> PolonskyKeerIteration::iterate(double tolerance) {
  // The passes' time is what the iteration's time leaves after the timed parts.
  const ContactTimings before = timings_;
  const auto start = std::chrono::steady_clock::now();
  const std::optional<ContactStatus> end = step(tolerance);
  timings_.passes += detail::seconds_since(start) - (timings_.steps - before.steps) -
                     (timings_.recomputations - before.recomputations) -
                     (timings_.preconditioner - before.preconditioner);
  return end;
}

std::optional<ContactStatus> PolonskyKeerIteration::step(double tolerance) {
  if (!exact_ || !update_by_linearity_) recompute_displacement();
  const std::ptrdiff_t n_contact = update_gap();
  if (n_contact == 0) return ContactStatus::pressure_vanished;
  WorkingSet working = select_working_set();
  if (working.norm == 0.0) {  // the gap is uniform on I_c: a solution if nothing overlaps elsewhere
    if (complementary(tolerance)) {
      residual_ = 0.0;
      return ContactStatus::converged;
    }
    widen_ = true;
    working = select_working_set();
  }
  // A widened set that gained no cell is I_c itself: the stop failed on the contact set's own
  // gaps, not on an overlap, and the conjugation goes on. A restart there would make every step
  // a steepest descent until the gaps meet eps (measured at a contrast of 1000: 880 such steps,
  // the residual below the tolerance all along, the gap error falling 10 % per 100 steps).
  if (widen_ && working.cells == n_contact) widen_ = false;
  update_direction(working.cells);
  const std::optional<double> tau = step_length(working.cells);
  widen_ = false;
  if (!tau) {
    // No curvature along t: t vanished to rounding because the gap is uniform on I_c to
    // rounding (on a small working set Polak-Ribiere's beta cancels what is left of z), which
    // is a solution if nothing overlaps; otherwise a true breakdown.
    if (complementary(tolerance)) {
      residual_ = 0.0;
      return ContactStatus::converged;
    }
    return ContactStatus::non_positive_curvature;
  }
  const Projected projected = project(*tau);
  if (!(projected.p_sum > 0) || !std::isfinite(projected.p_sum)) {
    p_.swap(p_old_);  // the last iterate that carried pressure; u is not its displacement
    scale_ = old_scale_;
    exact_ = false;
    return ContactStatus::pressure_vanished;
  }
  residual_ = enforce_load(projected);
  if (residual_ >= tolerance) return std::nullopt;
  // Polonsky & Keer's criterion says the iterate stopped moving; it is a solution only if the
  // complementarity conditions hold on every cell (docs/contact.md, "Convergence"). If they do
  // not, the next step takes the overlapping cells into its working set.
  if (!exact_) recompute_displacement();
  update_gap();
  if (complementary(tolerance)) return ContactStatus::converged;
  widen_ = true;
  return std::nullopt;
}

// Step 1: gap of the current pressure, g = h + u - delta; on the contact set I_c it should be
// constant (load control: its mean is the unknown approach, g_mean_) or zero (approach control).
// Returns the number of cells of I_c.
std::ptrdiff_t PolonskyKeerIteration::update_gap() {
  const double* hd = h_.data();
  const double* pd = p_.data();
  const double* ud = u_.data();
  double* gd = g_.data();
  const double s = scale_;
  const CountSum contact = detail::over_ranks(
      ranks_, over_cells<CountSum>(n_cells_, workers_, [&](auto first, auto last, CountSum& sums) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          gd[k] = hd[k] + s * ud[k] - delta_;
          if (pd[k] > 0) {
            ++sums.count;
            sums.sum += gd[k];
          }
        }
      }));
  if (contact.count > 0)
    g_mean_ = load_control_ ? contact.sum / static_cast<double>(contact.count) : 0.0;
  return contact.count;
}

// The cells a step moves, marked in working_: I_c, and after a stop with overlaps also the
// overlapping cells {p = 0, g < 0}. The preconditioner's input, P g, is written in the same pass
// (update_direction).
PolonskyKeerIteration::WorkingSet PolonskyKeerIteration::select_working_set() {
  const double* pd = p_.data();
  const double* gd = g_.data();
  unsigned char* wd = working_.data();
  double* zd = preconditioner_ ? preconditioner_->data() : nullptr;
  const CountSum working = detail::over_ranks(
      ranks_, over_cells<CountSum>(n_cells_, workers_, [&](auto first, auto last, CountSum& sums) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double g = gd[k] - g_mean_;
          const bool in = pd[k] > 0 || (widen_ && g < 0.0);
          wd[k] = in;
          if (in) {
            ++sums.count;
            sums.sum += g * g;
          }
          if (zd) zd[k] = in ? g : 0.0;
        }
      }));
  return {working.count, working.sum};
}

// The discrete complementarity conditions on every cell, for the gap update_gap left (u exact):
// p >= 0 holds by the projection; g >= -eps where p = 0 and |g| <= eps where p > 0 (p g = 0).
// eps is detail::gap_tolerance (docs/contact.md, "Convergence").
bool PolonskyKeerIteration::complementary(double tolerance) {
  const double* hd = h_.data();
  const double* pd = p_.data();
  const double* ud = u_.data();
  const double* gd = g_.data();
  struct Maxima {
    double u = 0.0, h = 0.0, violation = 0.0;
    Maxima& operator+=(const Maxima& o) {
      u = std::max(u, o.u);
      h = std::max(h, o.h);
      violation = std::max(violation, o.violation);
      return *this;
    }
  };
  const Maxima m = detail::over_ranks(
      ranks_, over_cells<Maxima>(n_cells_, workers_, [&](auto first, auto last, Maxima& s) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double g = gd[k] - g_mean_;
          s.u = std::max(s.u, std::abs(ud[k]));
          s.h = std::max(s.h, std::abs(hd[k]));
          s.violation = std::max(s.violation, pd[k] > 0 ? std::abs(g) : -g);
        }
      }));
  const double u_max = scale_ * m.u;
  const double largest_term = m.h + u_max + std::abs(delta_ + g_mean_);
  return m.violation <= detail::gap_tolerance(tolerance, u_max, largest_term);
}

// Polak-Ribiere's beta = max(0, z.(g - g_old)) / (g.z)_old, with Powell's (1977) restart: 0 when
// the gap has lost its orthogonality to the previous one, |z.g_old| >= 0.2 z.g. A change of the
// contact set breaks the conjugacy that a fixed set keeps; without the restart a stiff thin
// coating let the set cycle (a contrast of 1000: no convergence in 5000 iterations at 20 %
// contact, where the restart converges in 501; docs/contact.md, "Conjugation").
double polak_ribiere_beta(double g_dot_z, double q_dot_z, double g_dot_z_old) {
  constexpr double powell = 0.2;
  if (std::abs(q_dot_z) >= powell * g_dot_z) return 0.0;
  return std::max(0.0, (g_dot_z - q_dot_z) / g_dot_z_old);
}

// Step 2: search direction t on the working set (select_working_set). Preconditioned:
// z = P M P g with M ~ K^-1 (the |k| multiplier) and P the restriction to the working set (and,
// under load control, to zero mean on it, the tangent space of the load constraint); P M P is
// symmetric positive definite there, so this is preconditioned CG on the contact block, and a
// constant in g still cancels. Unpreconditioned: z = g. Then t = z + beta t (Conjugation),
// beta = 0 on the first step and on a widened working set. Two passes: one for the sums (z's
// mean and the products beta needs, the mean removed afterwards: sum w (z - m) = sum w z - m sum
// w), one that writes t (and keeps g for the next beta) on the working set and zeroes both on the
// cells that left it.
void PolonskyKeerIteration::update_direction(std::ptrdiff_t n_working) {
  if (preconditioner_) {  // select_working_set filled its field with P g
    const ScopedTimer timer(timings_.preconditioner);
    preconditioner_->apply();
  }
  const double* gd = g_.data();
  const double g_mean = g_mean_;
  // z: the preconditioned gap, or g itself (z - z_mean is then g - g_mean).
  const double* zd = preconditioner_ ? preconditioner_->data() : gd;
  const unsigned char* wd = working_.data();
  unsigned char* sd = direction_set_.data();
  double* td = t_.data();
  double* qd = g_prev_.size() > 0 ? g_prev_.data() : nullptr;
  struct Sums {
    double z = 0.0, g = 0.0, q = 0.0, t = 0.0, g_dot_z = 0.0, q_dot_z = 0.0;
    Sums& operator+=(const Sums& o) {
      z += o.z;
      g += o.g;
      q += o.q;
      t += o.t;
      g_dot_z += o.g_dot_z;
      q_dot_z += o.q_dot_z;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& s) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (!wd[k]) continue;
          const double g = gd[k] - g_mean;
          s.z += zd[k];
          s.g += g;
          s.t += td[k];
          s.g_dot_z += g * zd[k];
          if (qd) {
            s.q += qd[k];
            s.q_dot_z += qd[k] * zd[k];
          }
        }
      }));
  const auto n = static_cast<double>(n_working);
  // z's mean on the working set, removed under load control (P's zero-mean part).
  const double z_mean = !load_control_ ? 0.0 : preconditioner_ ? sums.z / n : g_mean;
  const double g_dot_z = sums.g_dot_z - (preconditioner_ ? z_mean : g_mean) * sums.g;
  const double q_dot_z = sums.q_dot_z - (preconditioner_ ? z_mean : g_mean) * sums.q;
  double beta = 0.0;
  if (conjugate_ && !widen_) {
    beta = conjugation_ == Conjugation::polak_ribiere
               ? polak_ribiere_beta(g_dot_z, q_dot_z, g_dot_z_old_)
               : g_dot_z / g_dot_z_old_;
  }
  // Under load control t must have zero mean on the working set too (the load constraint's
  // tangent space, where the step's curvature is positive): the previous direction had it on
  // its own working set, not necessarily on this one.
  const double t_mean = load_control_ ? sums.t / n : 0.0;
  over_cells<NoSums>(n_cells_, workers_, [&](auto first, auto last, NoSums&) {
    for (std::ptrdiff_t k = first; k < last; ++k) {
      if (wd[k]) {
        td[k] = zd[k] - z_mean + beta * (td[k] - t_mean);
        if (qd) qd[k] = gd[k] - g_mean;
      } else if (sd[k]) {
        td[k] = 0.0;
        if (qd) qd[k] = 0.0;
      }
      sd[k] = wd[k];
    }
  });
  g_dot_z_old_ = g_dot_z;
}

// Step 3: step length tau along t, or nothing when the curvature r.t is not positive. Under load
// control the mean of r = K t over I_c is removed: a constant displacement is absorbed by the
// approach, so it must not steer the step. This is also what makes the iterates independent of
// the operator's g(0). One pass: sum (r - m) t = sum r t - m sum t.
std::optional<double> PolonskyKeerIteration::step_length(std::ptrdiff_t n_working) {
  {
    const ScopedTimer timer(timings_.steps);
    op_.apply(t_, r_);
  }
  ++applications_;
  const double* gd = g_.data();
  const double* td = t_.data();
  const double* rd = r_.data();
  const unsigned char* wd = working_.data();
  const double g_mean = g_mean_;
  struct Sums {
    double r = 0.0, t = 0.0, g_dot_t = 0.0, r_dot_t = 0.0;
    Sums& operator+=(const Sums& o) {
      r += o.r;
      t += o.t;
      g_dot_t += o.g_dot_t;
      r_dot_t += o.r_dot_t;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& s) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (!wd[k]) continue;
          s.r += rd[k];
          s.t += td[k];
          s.g_dot_t += (gd[k] - g_mean) * td[k];
          s.r_dot_t += rd[k] * td[k];
        }
      }));
  const double r_mean = load_control_ ? sums.r / static_cast<double>(n_working) : 0.0;
  const double denominator = sums.r_dot_t - r_mean * sums.t;
  if (!(denominator > 0) || !std::isfinite(sums.g_dot_t)) return std::nullopt;
  return sums.g_dot_t / denominator;
}

// Step 4: p <- max(p - tau t, 0) (t is zero off the working set); cells that overlap (p = 0,
// g < 0) get pressure -tau g (and under Polonsky & Keer's rule restart the conjugation). The
// displacement follows by linearity, u <- u - tau r, which stays exact unless the projection
// changed a cell. The pending scale_ of p and u is applied here; the new pressure goes into
// p_old_'s field, and the two are swapped.
PolonskyKeerIteration::Projected PolonskyKeerIteration::project(double tau) {
  const double* gd = g_.data();
  const double* td = t_.data();
  const double* rd = r_.data();
  const unsigned char* wd = working_.data();
  const double* pd = p_.data();
  double* nd = p_old_.data();
  double* ud = u_.data();
  const double s = scale_;
  const double g_mean = g_mean_;
  struct Sums {
    double p = 0.0, change = 0.0;
    bool projected = false, added = false;
    Sums& operator+=(const Sums& o) {
      p += o.p;
      change += o.change;
      projected = projected || o.projected;
      added = added || o.added;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double p_old = s * pd[k];
          double pk = wd[k] ? p_old - tau * td[k] : p_old;
          if (pk < 0.0) {
            pk = 0.0;
            sum.projected = true;
          }
          if (pk == 0.0 && gd[k] < g_mean) {
            pk = -tau * (gd[k] - g_mean);
            sum.added = true;
            sum.projected = true;
          }
          nd[k] = pk;
          ud[k] = s * ud[k] - tau * rd[k];
          sum.p += pk;
          sum.change += std::abs(pk - p_old);
        }
      }));
  p_.swap(p_old_);
  old_scale_ = s;
  scale_ = 1.0;
  exact_ = exact_ && !sums.projected;
  conjugate_ = conjugation_ == Conjugation::polak_ribiere || !sums.added;
  return {sums.p, sums.change};
}

// Step 5: under load control the pressure (and with it u) is scaled to the total load exactly,
// by scale_, which the next projection applies. Returns Polonsky & Keer's convergence measure,
// the relative pressure change sum |s p - p_old| / sum s p of the scaled pressure, bounded from
// above without another pass: |s p - p_old| <= |p - p_old| + |s - 1| p. The bound is what the
// tolerance is held to (a stop it allows, the measure allows too).
double PolonskyKeerIteration::enforce_load(Projected projected) {
  const double s = load_control_ ? value_ / (projected.p_sum * cell_area_) : 1.0;
  scale_ = s;
  return (projected.change + std::abs(s - 1.0) * projected.p_sum) / (s * projected.p_sum);
}

ContactResult PolonskyKeerIteration::result(ContactStatus status, int iterations,
                                            bool compute_approach) {
  if (!exact_) recompute_displacement();
  p_ *= scale_;
  u_ *= scale_;
  scale_ = 1.0;
  const Mask contact = p_ > 0;
  const auto n_contact = detail::count_over(ranks_, contact.count());
  double approach = delta_;
  if (load_control_) {
    approach = n_contact > 0 ? masked_mean(h_ + u_, contact, n_contact, ranks_)
                             : detail::extrema_over(ranks_, h_).min;
  }
  ContactResult result;
  result.control = control_;
  result.gap = work_field(h_);
  result.gap = h_ + u_ - approach;
  result.pressure = std::move(p_);
  result.displacement = std::move(u_);
  result.load = detail::sum_over(ranks_, result.pressure.sum()) * cell_area_;
  if (!load_control_ || compute_approach) result.approach = approach;
  result.contact_area = static_cast<double>(n_contact) * cell_area_;
  if (n_contact > 0) result.contact_radius = std::sqrt(result.contact_area / std::numbers::pi);
  result.max_pressure = detail::extrema_over(ranks_, result.pressure).max;
  result.iterations = iterations;
  result.operator_applications = applications_;
  result.residual = residual_;
  result.status = status;
  result.converged = status == ContactStatus::converged;
  // A periodic surface has no edge: a contact crossing the period's border is just a contact.
  result.touches_boundary =
      !op_.periodic() && pressure_on_border(result.pressure, ranks_, op_.grid().ny());
  result.max_penetration = ranks_ ? std::max(0.0, -detail::extrema_over(ranks_, result.gap).min)
                                  : max_penetration(result.gap);
  return result;
}

// The sentence users see for a breakdown.
std::string breakdown_message(ContactStatus status) {
  return status == ContactStatus::pressure_vanished
             ? "all pressure vanished (breakdown)"
             : "non-positive curvature along the search direction (breakdown)";
}

// log2 of the displacement [m] a pressure of 1 Pa over the whole domain gives, estimated from
// one application: a unit pressure on one cell displaces by about dx / E*, a uniform one by the
// domain's width over E*, about that times the cells per side (an order of magnitude is enough).
double log2_compliance(SurfaceOperator& op, const SolverRanks* ranks) {
  const double cells_per_side = std::sqrt(static_cast<double>(op.grid().nb_cells()));
  const Field unit = op.unit_response();
  return std::log2(detail::extrema_over(ranks, unit.abs()).max) + std::log2(cells_per_side);
}

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
  }
  COATFFT_REQUIRE(
      std::isfinite(result.load) && std::isfinite(result.max_pressure) &&
          detail::all_over(ranks, result.displacement.allFinite() && result.gap.allFinite()),
      "ContactSolver: ", result.control == ContactControl::load ? "load" : "approach", " = ", value,
      ": the contact's pressure, displacement or gap leaves double precision; "
      "rescale the units of the load, the heights and the moduli");
}

}  // namespace

std::string_view to_string(ContactStatus status) {
  // In the order of the enumerators (tests/test_contact.cpp checks each name).
  static constexpr std::array<std::string_view, 5> names = {
      "converged", "iteration_limit", "pressure_vanished", "non_positive_curvature",
      "coupling_limit"};
  return names.at(static_cast<std::size_t>(status));
}

std::string describe(const ContactResult& result, double tolerance) {
  std::string text;
  const bool breakdown = result.status == ContactStatus::pressure_vanished ||
                         result.status == ContactStatus::non_positive_curvature;
  if (breakdown) append(text, breakdown_message(result.status));
  if (result.touches_boundary) {
    append(text,
           "contact reaches the domain edge (pressure > 0 on a border cell): the domain is too "
           "small for this load");
  }
  if (result.status == ContactStatus::coupling_limit) {
    append(text, "the friction coupling did not converge within its normal solves");
  }
  if (result.status == ContactStatus::iteration_limit) {
    append(text, detail::concat("not converged after ", result.iterations, " iterations (residual ",
                                result.residual, ", tolerance ", tolerance, ")"));
  }
  return text;
}

ContactSolver::ContactSolver(SurfaceOperator& op, ContactOptions options)
    : ContactSolver(op, std::move(options), nullptr) {}

ContactSolver::ContactSolver(SurfaceOperator& op, ContactOptions options,
                             std::shared_ptr<const detail::SolverRanks> ranks)
    : op_(op), options_(std::move(options)), ranks_(std::move(ranks)) {
  COATFFT_REQUIRE(std::isfinite(options_.tolerance) && options_.tolerance > 0,
                  "ContactSolver: tolerance = ", options_.tolerance,
                  ", but it must be finite and > 0");
  COATFFT_REQUIRE(options_.threads >= 1, "ContactSolver: threads = ", options_.threads,
                  ", but it must be >= 1");
  COATFFT_REQUIRE(options_.max_iterations >= 1,
                  "ContactSolver: max_iterations = ", options_.max_iterations,
                  ", but it must be >= 1");
  if (options_.preconditioned) {
    // Applied once per iteration: FFTW_MEASURE pays for its planning from 2048^2 cells
    // (docs/contact.md, "Preconditioning").
    constexpr std::ptrdiff_t measured_cells = 2048 * 2048;
    const Planning planning = options_.preconditioner_planning.value_or(
        op_.grid().nb_cells() >= measured_cells ? Planning::measure : Planning::estimate);
    if (ranks_) {
      preconditioner_ = ranks_->preconditioner(op_.grid(), options_.threads, planning);
    } else {
      auto fourier =
          std::make_unique<detail::FourierPreconditioner>(op_.grid(), options_.threads, planning);
      if (op_.periodic() &&
          options_.preconditioner_symbol == PreconditionerSymbol::operator_adapted) {
        fourier->adapt_to_kernel(op_.unit_response());
        pending_applications_ = 1;  // reported by the first solve
      }
      preconditioner_ = std::move(fourier);
    }
  }
}

ContactSolver::~ContactSolver() = default;

void ContactSolver::check_value(ContactControl control, double value) const {
  if (control == ContactControl::load)
    COATFFT_REQUIRE(std::isfinite(value) && value > 0, "ContactSolver: load = ", value,
                    " N, but the total load must be finite and > 0");
  else
    COATFFT_REQUIRE(std::isfinite(value), "ContactSolver: approach = ", value,
                    " m, but it must be finite");
}

ContactResult ContactSolver::solve_load(const Field& height, double load) {
  check_value(ContactControl::load, load);
  return run(height, ContactControl::load, load, std::nullopt);
}

ContactResult ContactSolver::solve_approach(const Field& height, double approach) {
  check_value(ContactControl::approach, approach);
  return run(height, ContactControl::approach, approach, std::nullopt);
}

ContactResult ContactSolver::solve(const Field& height, ContactControl control, double value) {
  return control == ContactControl::load ? solve_load(height, value)
                                         : solve_approach(height, value);
}

std::vector<ContactResult> ContactSolver::solve_sweep(const Field& height, ContactControl control,
                                                      std::vector<double> values) {
  COATFFT_REQUIRE(!values.empty(), "ContactSolver: a sweep needs at least one value");
  for (const double value : values) {  // all before any work
    check_value(control, value);
    check_problem(height, control, value);
  }
  std::sort(values.begin(), values.end());
  std::vector<ContactResult> results;
  for (const double value : values) {
    Field start;
    const std::size_t k = results.size();
    if (options_.on_value) options_.on_value(k, values.size(), value);
    if (k >= 2 && values[k - 1] > values[k - 2]) {
      // The secant through the last two solutions: exact while the contact set holds (p is then
      // linear in the load and in the approach). A repeated value starts from its twin.
      const double t = (value - values[k - 1]) / (values[k - 1] - values[k - 2]);
      start = results[k - 1].pressure + t * (results[k - 1].pressure - results[k - 2].pressure);
    } else if (k >= 1) {
      start = results[k - 1].pressure;
    }
    results.push_back(run(height, control, value,
                          k == 0 ? std::nullopt : std::optional<Field>(std::move(start))));
  }
  return results;
}

void ContactSolver::check_problem(const Field& h, ContactControl control, double value) const {
  const Grid& grid = op_.grid();
  const SolverRanks* ranks = ranks_.get();
  // Distributed: this rank's rows of the heights (every check is made by all ranks together).
  const std::ptrdiff_t rows = ranks ? ranks->rows() : grid.ny();
  COATFFT_REQUIRE(detail::all_over(ranks, h.rows() == grid.nx() && h.cols() == rows),
                  "ContactSolver: height field of shape (", h.rows(), ", ", h.cols(),
                  "), but the operator's grid is (", grid.nx(), ", ", grid.ny(), ")",
                  ranks ? " (distributed: a rank's rows)" : "");
  COATFFT_REQUIRE(detail::all_over(ranks, h.allFinite()),
                  "ContactSolver: the height field has a non-finite entry");
  if (control == ContactControl::approach) {
    const double h_min = detail::extrema_over(ranks, h).min;
    COATFFT_REQUIRE(value > h_min, "ContactSolver: approach = ", value,
                    " m, but it must exceed min(height) = ", h_min,
                    " m, or the indenter does not touch the surface");
    // A periodic displacement has zero mean (docs/theory.md 4.8), so the mean gap is
    // mean(h) - delta whatever the pressure: an approach at or beyond mean(h) has no solution
    // (the pressure would grow without bound). Full contact is reached as delta -> mean(h).
    const double h_mean =
        ranks ? detail::sum_over(ranks, h.sum()) / static_cast<double>(grid.nb_cells()) : h.mean();
    COATFFT_REQUIRE(!op_.periodic() || value < h_mean, "ContactSolver: approach = ", value,
                    " m, but on a periodic surface it must stay below mean(height) = ", h_mean,
                    " m (the displacement has zero mean: no contact solves a larger approach)");
  }
}

// Nested start: the coarse problem is the same contact on the coarse operator (the Galerkin
// product R K P) with the heights' 2 x 2 means R h and the same load or approach; its pressure,
// carried to the fine cells, starts the fine iteration near its solution, so the fine grid spends
// its iterations on what the coarse one cannot resolve (docs/contact.md, "Nested start"). Only
// where the heights below the trial level form more than one patch (a rough surface).
ContactSolver::NestedStart ContactSolver::nested_start(const Field& h, ContactControl control,
                                                       double value) {
  constexpr std::ptrdiff_t coarsest = 64;    // cells per side of the coarsest grid
  constexpr double coarse_tolerance = 1e-3;  // a start needs no more (docs/contact.md)
  const Grid& grid = op_.grid();
  // Not on distributed fields yet: their coarse grids' rows would not pair up within a rank.
  if (ranks_ || !options_.nested_start || grid.nx() % 2 != 0 || grid.ny() % 2 != 0 ||
      std::min(grid.nx(), grid.ny()) < 2 * coarsest)
    return {};
  // One patch below the trial level (a smooth indenter) is what the Hertzian start describes
  // nearly exactly: there the coarse solves would cost more than they spare (docs/contact.md).
  const double level = detail::level_below(h, detail::kTrialContactShare);
  if (detail::count_patches(h < level, op_.periodic()) <= 1) return {};
  Field h_coarse = detail::restrict_by_mean(h);
  // The means' minimum lies above min(h): an approach just beyond min(h) may miss them.
  if (control == ContactControl::approach && !(value > h_coarse.minCoeff())) return {};
  const std::unique_ptr<SurfaceOperator> coarse = op_.coarsened();
  if (!coarse) return {};
  NestedStart nested;
  nested.applications = 1;  // coarsened()'s unit response
  ContactOptions options = options_;
  options.tolerance = std::max(options_.tolerance, coarse_tolerance);
  options.compute_approach = false;
  options.on_iteration = nullptr;
  options.preconditioner_planning = Planning::estimate;  // a few cheap iterations
  ContactSolver solver(*coarse, options);
  const ContactResult result = solver.solve(h_coarse, control, value);
  nested.coarse_applications = result.operator_applications + result.coarse_applications;
  if (result.pressure.sum() > 0) nested.pressure = detail::prolong_by_cell(result.pressure);
  return nested;
}

ContactResult ContactSolver::run(const Field& h, ContactControl control, double value,
                                 std::optional<Field> start) {
  check_problem(h, control, value);
  const auto solve_start = std::chrono::steady_clock::now();
  NestedStart nested;
  if (!start) {
    nested = nested_start(h, control, value);
    start = std::move(nested.pressure);
  }
  int scale_applications = nested.applications;
  const double s = control == ContactControl::load
                       ? load_scale(op_, h, value, scale_applications, ranks_.get())
                       : 1.0;
  Field h_scaled;
  if (s != 1.0) {
    h_scaled = work_field(h);
    h_scaled = h / s;
  }
  COATFFT_REQUIRE(
      s == 1.0 || (detail::all_over(ranks_.get(), h_scaled.allFinite()) && value / s > 0),
      "ContactSolver: load = ", value, " N and heights spanning ",
      detail::extrema_over(ranks_.get(), h).max - detail::extrema_over(ranks_.get(), h).min,
      " m are too far apart for double precision; rescale their units");
  PolonskyKeerIteration iteration(op_, preconditioner_.get(), ranks_.get(), s == 1.0 ? h : h_scaled,
                                  control, value / s, options_, std::move(start));
  const double start_seconds = detail::seconds_since(solve_start);
  iteration.timings() = ContactTimings{};  // the start's recomputations are the start's
  ContactStatus status = ContactStatus::iteration_limit;
  int iterations = 0;
  while (iterations < options_.max_iterations) {
    // The iterate lives here and is dropped on the way out: the operator and the solver are
    // left as they were, ready for another solve.
    // Distributed, the ranks stop together: one that stopped alone would leave the others
    // waiting in the next sum.
    if (!ranks_) {
      check_interrupt();
    } else if (!detail::all_over(ranks_.get(), !detail::poll_interrupt())) {
      throw Interrupted();
    }
    ++iterations;
    const std::optional<ContactStatus> end = iteration.iterate(options_.tolerance);
    const bool stepped = !end || *end == ContactStatus::converged;
    if (stepped && options_.on_iteration) options_.on_iteration(iterations, iteration.residual());
    if (end) {
      status = *end;
      break;
    }
  }
  ContactResult result = iteration.result(status, iterations, options_.compute_approach);
  result.timings = iteration.timings();
  result.timings.start = start_seconds;
  result.timings.total = detail::seconds_since(solve_start);
  result.operator_applications += scale_applications + std::exchange(pending_applications_, 0);
  result.coarse_applications = nested.coarse_applications;
  unscale(result, s, value, ranks_.get());
  result.warning = describe(result, options_.tolerance);
  return result;
}

}  // namespace coatfft
