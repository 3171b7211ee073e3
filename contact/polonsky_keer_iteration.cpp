#include "contact/detail/polonsky_keer_iteration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "contact/detail/cell_passes.hpp"
#include "contact/detail/scoped_timer.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "core/detail/timing.hpp"

namespace coatfft::detail {

namespace {

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

}  // namespace

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
      u_(options.hardness ? work_field(h) : Field()),
      g_(work_field(h)),
      t_(zero_field(h)),  // read (times beta = 0) by the first iteration
      r_(work_field(h)),
      cell_sets_(clear_mask(h)),
      conjugation_(options.conjugation),
      update_by_linearity_(options.update_by_linearity),
      cap_(options.hardness.value_or(std::numeric_limits<double>::infinity())),
      capped_(options.hardness.has_value()) {
  if (conjugation_ == Conjugation::polak_ribiere) g_prev_ = zero_single_field(h);
  start(start_pressure.has_value());
  if (capped_) start_under_cap();
}

void PolonskyKeerIteration::recompute_displacement() {
  const ScopedTimer timer(timings_.recomputations);
  if (v_.size() == 0) {
    op_.apply(p_, displacement());
    ++applications_;
    g_is_displacement_ = !capped_;
    exact_ = true;
    return;
  }
  // Under a cap the two parts (v_'s comment); r_ is free between steps.
  r_ = (p_ < cap_).select(p_, 0.0);
  op_.apply(r_, u_);
  ++applications_;
  if (!plastic_exact_) {
    r_ = (p_ >= cap_).select(p_, 0.0);
    op_.apply(r_, v_);
    ++applications_;
    plastic_exact_ = true;
  }
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
  const bool widened = widen_;
  update_direction(working.cells);
  const std::optional<double> tau = step_length(working.cells);
  widen_ = false;
  if (!tau) {
    // No curvature along t: t vanished to rounding because the gap is uniform on I_c to
    // rounding (on a small working set Polak-Ribiere's beta cancels what is left of z), which
    // is a solution if nothing overlaps; otherwise a true breakdown. Under a cap, I_c may be a
    // cell or none (the others at the cap) while cells at the cap or outside violate their
    // conditions: the next step takes those in.
    if (complementary(tolerance)) {
      residual_ = 0.0;
      return ContactStatus::converged;
    }
    if (capped_ && !widened) {
      widen_ = true;
      return std::nullopt;
    }
    return ContactStatus::non_positive_curvature;
  }
  const Projected projected = project(*tau);
  if (!(projected.p_sum > 0) || !std::isfinite(projected.p_sum)) {
    p_.swap(r_);  // the last iterate that carried pressure; u is not its displacement
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

// Step 1: gap of the current pressure, g = h + u - delta; on the contact set I_c (the cells
// with 0 < p < cap) it should be constant (load control: its mean is the unknown approach,
// g_mean_) or zero (approach control). Returns the number of cells with p > 0. Without a cap g_
// is formed from what it holds: K p after a recomputation (g = h + s g - delta), else the gap of
// gap_scale_ p (rescaled to s p, g = r g + (1 - r) (h - delta) with r = s / gap_scale_: nothing
// to write when r = 1, as under approach control). Under a cap, from its two parts u_ and v_.
std::ptrdiff_t PolonskyKeerIteration::update_gap() {
  const double* hd = h_.data();
  const double* pd = p_.data();
  double* gd = g_.data();
  const double* ud = capped_ ? u_.data() : gd;
  const double* vd = v_.size() > 0 ? v_.data() : nullptr;
  const double s = scale_;
  const double cap = cap_;
  const double delta = delta_;
  const bool from_displacement = capped_ || g_is_displacement_;
  const double ratio = from_displacement ? 1.0 : s / gap_scale_;
  const bool rescale = !from_displacement && ratio != 1.0;
  // The free cells' gaps are summed about the previous mean: a plain sum of values near the
  // approach rounds in proportion to the cells in contact, which set a floor under every gap
  // the stop can check (2e-11 of u_max at 4096^2, above the default 1e-10 at 16384^2).
  const double shift = g_mean_;
  struct Sums {
    std::ptrdiff_t carrying = 0;
    CountSum free;
    double g_max = -std::numeric_limits<double>::infinity();  // over the carrying cells
    Sums& operator+=(const Sums& o) {
      carrying += o.carrying;
      free += o.free;
      g_max = std::max(g_max, o.g_max);
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (from_displacement) {
            gd[k] = hd[k] + s * ud[k] - delta;
            if (vd) gd[k] += vd[k];
          } else if (rescale) {
            gd[k] = ratio * gd[k] + (1.0 - ratio) * (hd[k] - delta);
          }
          if (pd[k] > 0) {
            ++sum.carrying;
            sum.g_max = std::max(sum.g_max, gd[k]);
            if (pd[k] < cap) {
              ++sum.free.count;
              sum.free.sum += gd[k] - shift;
            }
          }
        }
      }));
  g_is_displacement_ = false;
  gap_scale_ = s;
  if (!load_control_) {
    g_mean_ = 0.0;
  } else if (sums.free.count > 0) {
    g_mean_ = shift + sums.free.sum / static_cast<double>(sums.free.count);
  } else if (sums.carrying > 0) {
    // Every carrying cell at the cap: the approach is bounded, not fixed, by the cells; the
    // least that leaves no cell at the cap with an open gap.
    g_mean_ = sums.g_max;
  }
  return sums.carrying;
}

// The cells a step moves, marked kWorking in cell_sets_: I_c, and after a stop with overlaps also
// the overlapping cells {p = 0, g < 0} and the cells at the cap that would carry less, {p = cap, g
// > 0}. The preconditioner's input, P g, is written in the same pass (update_direction).
PolonskyKeerIteration::WorkingSet PolonskyKeerIteration::select_working_set() {
  const double* pd = p_.data();
  const double* gd = g_.data();
  unsigned char* wd = cell_sets_.data();
  double* zd = preconditioner_ ? r_.data() : nullptr;
  const double cap = cap_;
  const CountSum working = detail::over_ranks(
      ranks_, over_cells<CountSum>(n_cells_, workers_, [&](auto first, auto last, CountSum& sums) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double g = gd[k] - g_mean_;
          const bool in = pd[k] >= cap ? widen_ && g > 0.0 : pd[k] > 0 || (widen_ && g < 0.0);
          wd[k] = static_cast<unsigned char>((wd[k] & kDirectionSet) | (in ? kWorking : 0));
          if (in) {
            ++sums.count;
            sums.sum += g * g;
          }
          if (zd) zd[k] = in ? g : 0.0;
        }
      }));
  return {working.count, working.sum};
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
    preconditioner_->apply(r_.data());
  }
  const double g_mean = g_mean_;
  const DirectionSums sums = direction_sums();
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
  write_direction(z_mean, beta, t_mean);
  g_dot_z_old_ = g_dot_z;
}

// update_direction's first pass: its sums over the working set (z: the preconditioned gap, or g
// itself, whose z - z_mean is then g - g_mean).
PolonskyKeerIteration::DirectionSums PolonskyKeerIteration::direction_sums() {
  const double* gd = g_.data();
  const double g_mean = g_mean_;
  const double* zd = preconditioner_ ? r_.data() : gd;
  const unsigned char* wd = cell_sets_.data();
  const double* td = t_.data();
  const float* qd = g_prev_.size() > 0 ? g_prev_.data() : nullptr;
  return detail::over_ranks(
      ranks_,
      over_cells<DirectionSums>(n_cells_, workers_, [&](auto first, auto last, DirectionSums& s) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          if (!(wd[k] & kWorking)) continue;
          const double g = gd[k] - g_mean;
          s.z += zd[k];
          s.g += g;
          s.t += td[k];
          s.g_dot_z += g * zd[k];
          if (qd) {
            const double q = qd[k];
            s.q += q;
            s.q_dot_z += q * zd[k];
          }
        }
      }));
}

// update_direction's second pass: t = z - z_mean + beta (t - t_mean) (and g kept for the next
// beta) on the working set; both zeroed on the cells that left it.
void PolonskyKeerIteration::write_direction(double z_mean, double beta, double t_mean) {
  const double* gd = g_.data();
  const double g_mean = g_mean_;
  const double* zd = preconditioner_ ? r_.data() : gd;
  unsigned char* wd = cell_sets_.data();
  double* td = t_.data();
  float* qd = g_prev_.size() > 0 ? g_prev_.data() : nullptr;
  over_cells<NoSums>(n_cells_, workers_, [&](auto first, auto last, NoSums&) {
    for (std::ptrdiff_t k = first; k < last; ++k) {
      const unsigned char sets = wd[k];
      if (sets & kWorking) {
        td[k] = zd[k] - z_mean + beta * (td[k] - t_mean);
        if (qd) qd[k] = static_cast<float>(gd[k] - g_mean);
      } else if (sets & kDirectionSet) {
        td[k] = 0.0;
        if (qd) qd[k] = 0.0f;
      }
      wd[k] = (sets & kWorking) ? static_cast<unsigned char>(kWorking | kDirectionSet) : 0;
    }
  });
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
  const unsigned char* wd = cell_sets_.data();
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
          if (!(wd[k] & kWorking)) continue;
          s.r += rd[k];
          s.t += td[k];
          s.g_dot_t += (gd[k] - g_mean) * td[k];
          s.r_dot_t += rd[k] * td[k];
        }
      }));
  const double r_mean = load_control_ ? sums.r / static_cast<double>(n_working) : 0.0;
  const double denominator = sums.r_dot_t - r_mean * sums.t;
  if (!(denominator > 0) || !std::isfinite(sums.g_dot_t)) return std::nullopt;
  // Under a cap the working set can shrink to a few cells of one gap (the others at the cap),
  // where t is rounding and may point uphill: no step along it (step() then checks for a
  // solution, or widens the set).
  if (capped_ && !(sums.g_dot_t > 0)) return std::nullopt;
  return sums.g_dot_t / denominator;
}

// Step 4: p <- max(p - tau t, 0) (t is zero off the working set); cells that overlap (p = 0,
// g < 0) get pressure -tau g (and under Polonsky & Keer's rule restart the conjugation). Under a
// cap, p <- min(p, cap), and cells at the cap whose gap opens (g > 0) get cap - tau g: the mirror
// of the overlapping cells. The gap follows by linearity, g <- g - tau r (under a cap the
// displacement of the cells below it, u <- u - tau r), which stays exact unless the projection
// changed a cell (plastic_exact_ too, unless one reached or left the cap). The pending scale_ of
// p (and of g, which update_gap applied) is applied here; the new pressure goes into r's field
// (each cell's r read before), and p and r are swapped: until the next step writes r, it holds
// the previous pressure (unscaled, old_scale_ its factor).
PolonskyKeerIteration::Projected PolonskyKeerIteration::project(double tau) {
  double* gd = g_.data();
  const double* td = t_.data();
  const double* rd = r_.data();
  const unsigned char* wd = cell_sets_.data();
  const double* pd = p_.data();
  double* nd = r_.data();  // r is read at a cell before the new pressure is written there
  // What the step moves by linearity: the gap itself (of s p since update_gap), or under a cap
  // the displacement of the cells below it.
  double* ud = capped_ ? u_.data() : gd;
  const double s = scale_;
  const double u_scale = capped_ ? s : 1.0;
  const double g_mean = g_mean_;
  const double cap = cap_;
  struct Sums {
    double p = 0.0, change = 0.0, free = 0.0, free_max = 0.0;
    std::ptrdiff_t at_cap = 0;
    bool projected = false, added = false, plastic = false;
    Sums& operator+=(const Sums& o) {
      p += o.p;
      change += o.change;
      free += o.free;
      free_max = std::max(free_max, o.free_max);
      at_cap += o.at_cap;
      projected = projected || o.projected;
      added = added || o.added;
      plastic = plastic || o.plastic;
      return *this;
    }
  };
  const Sums sums = detail::over_ranks(
      ranks_, over_cells<Sums>(n_cells_, workers_, [&](auto first, auto last, Sums& sum) {
        for (std::ptrdiff_t k = first; k < last; ++k) {
          const double p_old = s * pd[k];
          const bool working = wd[k] & kWorking;
          double pk = working ? p_old - tau * td[k] : p_old;
          if (pk < 0.0) {
            pk = 0.0;
            sum.projected = true;
          }
          if (pk == 0.0 && gd[k] < g_mean) {
            pk = -tau * (gd[k] - g_mean);
            sum.added = true;
            sum.projected = true;
          }
          if (pk >= cap) {  // never without a cap (infinity)
            if (!working && gd[k] > g_mean) pk = std::max(0.0, cap - tau * (gd[k] - g_mean));
            pk = std::min(pk, cap);
          }
          if ((pk >= cap || p_old >= cap) && pk != p_old) {
            sum.plastic = true;
            sum.projected = true;
          }
          ud[k] = u_scale * ud[k] - tau * rd[k];
          nd[k] = pk;
          sum.p += pk;
          sum.change += std::abs(pk - p_old);
          if (pk >= cap) {
            ++sum.at_cap;
          } else {
            sum.free += pk;
            sum.free_max = std::max(sum.free_max, pk);
          }
        }
      }));
  p_.swap(r_);
  old_scale_ = s;
  scale_ = 1.0;
  gap_scale_ = 1.0;
  exact_ = exact_ && !sums.projected;
  plastic_exact_ = plastic_exact_ && !sums.plastic;
  conjugate_ = conjugation_ == Conjugation::polak_ribiere || !sums.added;
  return {sums.p, sums.change, sums.free, sums.free_max, sums.at_cap};
}

// Step 5: under load control the pressure (and with it u) is scaled to the total load exactly,
// by scale_, which the next projection applies. Returns Polonsky & Keer's convergence measure,
// the relative pressure change sum |s p - p_old| / sum s p of the scaled pressure, bounded from
// above without another pass: |s p - p_old| <= |p - p_old| + |s - 1| p. The bound is what the
// tolerance is held to (a stop it allows, the measure allows too).
double PolonskyKeerIteration::enforce_load(Projected projected) {
  if (capped_ && load_control_) return restore_load_under_cap(projected);
  const double s = load_control_ ? value_ / (projected.p_sum * cell_area_) : 1.0;
  scale_ = s;
  return (projected.change + std::abs(s - 1.0) * projected.p_sum) / (s * projected.p_sum);
}

}  // namespace coatfft::detail
