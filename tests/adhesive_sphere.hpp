#pragma once
// The adhesive sphere of the adhesion tests (tests/test_adhesion.cpp, the quick ones;
// tests/test_adhesion_grid.cpp, the finer grids): a rigid sphere on a soft half-space with a
// Dugdale law of Maugis' lambda, and an approach path through pull-off against Maugis-Dugdale.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "contact/adhesive_contact.hpp"
#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "validation/maugis_dugdale.hpp"

namespace coatfft_test {

using namespace coatfft;

// A rigid sphere (R = 1 mm) on a soft half-space (E* = 1 GPa) with w = 0.05 J/m^2; sigma0 from
// Maugis' lambda. Lengths in Maugis' scales: a_s = (pi w R^2 / K)^(1/3) = 4.9 um, d_s = (pi^2 w^2
// R / K^2)^(1/3) = 0.24 um.
struct AdhesiveBall {
  double radius = 1e-3, modulus = 1e9, work = 0.05;
  double lambda = 1.0;
  Material body{modulus * (1 - 0.3 * 0.3), 0.3};
  AdhesionOptions law() const {
    const double k = 4 * modulus / 3;
    const double sigma0 = 0.5 * lambda * std::cbrt(std::numbers::pi * work * k * k / radius);
    return {work, work / sigma0};
  }
  MaugisDugdale reference() const { return {radius, modulus, work, law().range}; }
  double a_scale() const {
    return std::cbrt(std::numbers::pi * work * radius * radius / (4 * modulus / 3));
  }
  double d_scale() const {
    const double k = 4 * modulus / 3;
    return std::cbrt(std::numbers::pi * std::numbers::pi * work * work * radius / (k * k));
  }
  /// Maugis-Dugdale's pull-off over pi w R.
  double reference_pull_off() const {
    return reference().pull_off_load() / (std::numbers::pi * work * radius);
  }
};

// The approach path of the tests: from D = 2 (Maugis' approach scale) down in steps of 0.1 until
// the contact has jumped off or D = -2.
inline std::vector<double> falling_approaches(const AdhesiveBall& ball) {
  std::vector<double> approaches;
  for (int k = 20; k >= -20; --k) approaches.push_back(0.1 * k * ball.d_scale());
  return approaches;
}

struct PathCheck {
  double pull_off = 0;          // the most tensile load of the path, over pi w R
  double worst_load_error = 0;  // over the steps in contact on the reference's branch, / pi w R
  bool all_converged = true;
};

inline PathCheck run_path(const AdhesiveBall& ball, std::ptrdiff_t n, double span,
                          const LayerStack& body, OperatorOptions o = {}) {
  const double l = span * ball.a_scale();
  const Grid g(n, n, l, l);
  const BuiltOperator built = make_operator(g, body, o);
  ContactSolver solver(*built.op);
  const Field h = height(g, Sphere{ball.radius});
  const std::vector<double> approaches = falling_approaches(ball);
  const std::vector<AdhesiveResult> path =
      solve_adhesive_path(solver, h, ContactControl::approach, approaches, ball.law());
  const MaugisDugdale md = ball.reference();
  const double scale = std::numbers::pi * ball.work * ball.radius;
  PathCheck c;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const AdhesiveResult& r = path[k];
    c.all_converged = c.all_converged && r.converged;
    c.pull_off = std::min(c.pull_off, r.contact.load / scale);
    const double reference = md.load_at_approach(approaches[k]);
    if (r.contact_area > 0 && std::isfinite(reference))
      c.worst_load_error =
          std::max(c.worst_load_error, std::abs(r.contact.load - reference) / scale);
  }
  return c;
}
}  // namespace coatfft_test
