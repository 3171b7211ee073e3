#pragma once
// An independent solver of the capped contact for the tests: the same discrete problem as the
// contact solver's, min 1/2 p.K p + p.(h - delta) over 0 <= p <= H (approach control), or over
// the same box with sum p dx dy = W (load control, h alone: the approach is the constraint's
// multiplier), solved by accelerated projected gradients (FISTA, Beck & Teboulle 2009, with
// O'Donoghue & Candes 2015's adaptive restart) on the operator itself. It shares nothing with
// the contact solver but the operator: no working set, no conjugation, the projection onto the
// box (and the load's hyperplane) made exactly, by bisection on its shift.
#include <algorithm>
#include <cmath>

#include "contact/contact_solver.hpp"
#include "convolution/operators/surface_operator.hpp"
#include "core/types.hpp"

namespace coatfft::test {

// The Euclidean projection of y onto {0 <= p <= cap} and {sum p = load_sum}: p = clip(y - c, 0,
// cap), the shift c found by bisection (sum p is monotone in c).
inline Field project_onto_loaded_box(const Field& y, double cap, double load_sum) {
  const auto sum_at = [&](double c) { return (y - c).max(0.0).min(cap).sum(); };
  double lo = y.minCoeff() - cap, hi = y.maxCoeff();  // sum_at(lo) = n cap, sum_at(hi) = 0
  for (int k = 0; k < 200 && hi - lo > 1e-16 * (std::abs(lo) + std::abs(hi)); ++k) {
    const double mid = 0.5 * (lo + hi);
    (sum_at(mid) > load_sum ? lo : hi) = mid;
  }
  return (y - 0.5 * (lo + hi)).max(0.0).min(cap);
}

// The largest eigenvalue of the (symmetric, positive) operator, by power iteration, with a
// margin: the gradient step 1/L must not exceed the inverse curvature.
inline double largest_eigenvalue(SurfaceOperator& op) {
  Field x = Field::Constant(op.grid().nx(), op.grid().ny(), 1.0);
  x(0, 0) = 2.0;  // not an eigenvector of a periodic operator
  double lambda = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Field y = op.apply(x);
    lambda = std::sqrt(y.square().sum() / x.square().sum());
    x = y / std::sqrt(y.square().sum());
  }
  return 1.05 * lambda;
}

struct BoxQpSolution {
  Field pressure;
  int iterations = 0;
  double step_change = 0;  // max |p_k+1 - p_k| / cap of the last step
};

// FISTA until a step moves no cell by more than `tolerance` times the cap.
inline BoxQpSolution solve_box_qp(SurfaceOperator& op, const Field& h, double cap,
                                  ContactControl control, double value, double tolerance,
                                  int max_iterations = 200000) {
  const double step = 1.0 / largest_eigenvalue(op);
  const double cell_area = op.grid().dx() * op.grid().dy();
  const bool loaded = control == ContactControl::load;
  const auto project = [&](const Field& y) {
    return loaded ? project_onto_loaded_box(y, cap, value / cell_area) : Field(y.max(0.0).min(cap));
  };
  const Field linear = loaded ? h : Field(h - value);
  Field p = project(Field::Zero(h.rows(), h.cols()));
  Field y = p;
  double t = 1.0;
  BoxQpSolution s;
  for (s.iterations = 1; s.iterations <= max_iterations; ++s.iterations) {
    const Field gradient = op.apply(y) + linear;
    const Field next = project(y - step * gradient);
    s.step_change = (next - p).abs().maxCoeff() / cap;
    // Restart when the momentum points uphill (gradient-based test).
    const bool restart = (gradient * (next - p)).sum() > 0;
    const double t_next = restart ? 1.0 : 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
    y = restart ? next : Field(next + ((t - 1.0) / t_next) * (next - p));
    p = next;
    t = t_next;
    if (s.step_change < tolerance) break;
  }
  s.pressure = p;
  return s;
}

}  // namespace coatfft::test
