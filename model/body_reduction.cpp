#include "model/body_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>

#include "core/detail/brief.hpp"
#include "core/error.hpp"
#include "core/gsl_quadrature.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

// Below t = k a = t_exact the integrands are integrated as they are (oscillating, over panels
// of one half-period); beyond, |P| is replaced by its envelope, which is smooth (panels doubling
// in k); beyond t_end the tail is bounded analytically.
constexpr double t_exact = 200.0;
constexpr double t_end = 1e8;
constexpr double rel_tol = 1e-4;
// The scene's load is not the reference load: its piecewise-constant cells, and a shape only
// approximated by the reference, move the true effect off the bound where the bound is tight (a
// thick coating: the FRFs differ at small k only, where P > 0, and the bound is the centre's
// value: 0.1 % below the discrete difference at 64^2). The margin covers that.
constexpr double reference_margin = 1.5;

// Envelope of |P(k)| for t = k a >= t_exact: Hertz 2 pi a^2 (1 + t)/t^3 (|sin t - t cos t| <=
// 1 + t); uniform disk 2 pi a^2 sqrt(2/(pi t)) (1 + 1/t) / t (Hankel's asymptotic form of J1 with
// its first correction bounded by 1/t; Abramowitz & Stegun 9.2.1).
double load_envelope(const ReferenceLoad& load, double k) {
  const double a = load.radius;
  const double t = k * a;
  if (load.shape == AxisymmetricLoad::hertz) return 2 * pi * a * a * (1 + t) / (t * t * t);
  return 2 * pi * a * a * std::sqrt(2 / (pi * t)) * (1 + 1 / t) / t;
}

// \int_{k_end}^inf of (k |dH| bounded by `kdh_end`) times the envelope, dk / k: Hertz
// 2 pi a^2 (1 + t)/t^3 <= 4 pi a^2/t^2 gives 4 pi a^2 / t_end (per unit of kdH, in k: / a ... a);
// the disk's t^-3/2 gives 2 pi a^2 sqrt(2/pi) 2/sqrt(t_end).
double tail_bound(const ReferenceLoad& load, double kdh_end) {
  const double a = load.radius;
  // \int |dH| E k dk = \int (k |dH|) E dk, and dk = dt / a.
  if (load.shape == AxisymmetricLoad::hertz) return kdh_end * 4 * pi * a / t_end;
  return kdh_end * 2 * pi * a * std::sqrt(2 / pi) * 2 / std::sqrt(t_end);
}

// Each panel to rel_tol of itself or `abs_tol` (a small fraction of u(0): the panels where the
// FRFs agree to rounding need not be resolved).
double integrate(const std::function<double(double)>& f, double a, double b, double abs_tol,
                 gsl_integration_workspace* ws) {
  return gsl_qag(f, a, b, abs_tol, rel_tol, GSL_INTEG_GAUSS21, ws).value;
}

// \int_0^{t_exact/a} f dk over panels of half a period of the load's oscillation.
double integrate_oscillating(const std::function<double(double)>& f, double a, double abs_tol,
                             gsl_integration_workspace* ws) {
  double sum = 0.0;
  for (double t = 0.0; t < t_exact; t += pi / 2)
    sum += integrate(f, t / a, std::min(t + pi / 2, t_exact) / a, abs_tol, ws);
  return sum;
}

}  // namespace

double reduction_effect(const Frf& full, const Frf& reduced, const ReferenceLoad& load) {
  COATFFT_REQUIRE(std::isfinite(load.radius) && load.radius > 0,
                  "reduction_effect: radius = ", load.radius, " m, but it must be finite and > 0");
  const GslHandlerOff quiet;
  const GslWorkspace ws = make_gsl_workspace(200);
  const double a = load.radius;
  const auto dh = [&](double k) { return std::abs(full(k) - reduced(k)); };
  const auto transform = [&](double k) {
    return axisymmetric_load_transform(load.shape, 1.0, a, k);
  };
  // 2 pi u(0) = \int H P k dk, the denominator.
  const double u0 = 2 * pi * hankel_displacement(full, load.shape, 1.0, a, 0.0, 1e-8);
  const double abs_tol = 1e-8 * std::abs(u0);
  double diff = integrate_oscillating([&](double k) { return dh(k) * std::abs(transform(k)) * k; },
                                      a, abs_tol, ws.get());
  for (double t = t_exact; t < t_end; t *= 2) {
    diff += integrate([&](double k) { return dh(k) * load_envelope(load, k) * k; }, t / a,
                      std::min(2 * t, t_end) / a, abs_tol, ws.get());
  }
  // Beyond t_end, k |dH| is at its limit |Cinf_full - Cinf_reduced| (the layers' exponential
  // terms are e^-(k h) small there unless a layer is thinner than a / 1e6); the larger of the
  // limit and the last value bounds it.
  const double k_end = t_end / a;
  const double kdh = std::max(k_end * dh(k_end), std::abs(full.c_inf() - reduced.c_inf()));
  diff += tail_bound(load, kdh);
  COATFFT_REQUIRE(std::isfinite(diff) && u0 > 0, "reduction_effect: the bound is not finite (",
                  diff, " / ", u0, ") for FRFs '", full.name(), "' and '", reduced.name(), "'");
  return reference_margin * diff / u0;
}

namespace {

// Layer i and the medium below it become one layer of the lower material and their total
// thickness; the last coating joins the substrate.
LayerStack merged(const LayerStack& stack, std::size_t i) {
  std::vector<Coating> c = stack.coatings();
  if (i + 1 < c.size()) c[i + 1].thickness += c[i].thickness;
  c.erase(c.begin() + static_cast<std::ptrdiff_t>(i));
  return c.empty() ? LayerStack(stack.substrate()) : LayerStack(c, stack.substrate());
}

struct Trial {
  LayerStack body;
  double effect;
};

double largest_effect(const Frf& full, const LayerStack& reduced,
                      const std::vector<ReferenceLoad>& loads) {
  const std::unique_ptr<Frf> frf = make_frf(reduced);
  double effect = 0.0;
  for (const ReferenceLoad& load : loads)
    effect = std::max(effect, reduction_effect(full, *frf, load));
  return effect;
}

// The merge of one pair of `current` with the smallest effect on `full`.
Trial best_merge(const Frf& full, const LayerStack& current,
                 const std::vector<ReferenceLoad>& loads) {
  Trial best{current, std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < current.coatings().size(); ++i) {
    LayerStack candidate = merged(current, i);
    const double effect = largest_effect(full, candidate, loads);
    if (effect < best.effect) best = {std::move(candidate), effect};
  }
  return best;
}

std::string describe(const BodyReduction& r, double budget) {
  if (r.kind == "none")
    return detail::concat(
        "no simpler body is within the budget ", detail::brief(budget),
        " (smallest effect of a reduction tried: ",
        detail::brief(r.tried.empty()
                          ? 0.0
                          : std::min_element(r.tried.begin(), r.tried.end(),
                                             [](auto& x, auto& y) { return x.second < y.second; })
                                ->second),
        ")");
  return detail::concat(r.kind, ": estimated effect ", detail::brief(r.estimated_effect),
                        " <= budget ", detail::brief(budget));
}

}  // namespace

BodyReduction reduce_body(const LayerStack& stack, const std::vector<ReferenceLoad>& loads,
                          double budget) {
  COATFFT_REQUIRE(std::isfinite(budget) && budget > 0, "reduce_body: budget = ", budget,
                  ", but it must be finite and > 0");
  COATFFT_REQUIRE(!loads.empty(), "reduce_body: no reference load");
  BodyReduction r{stack, "none", 0.0, "the body is homogeneous", {}};
  if (stack.is_homogeneous()) return r;
  const std::unique_ptr<Frf> full = make_frf(stack);
  // Homogeneous bodies first: Love's exact DC-FFT then applies.
  const LayerStack homogeneous[2] = {LayerStack(stack.substrate()),
                                     LayerStack(stack.coatings().front().material)};
  const char* kinds[2] = {"substrate", "top_half_space"};
  for (int i = 0; i < 2; ++i) {
    const double effect = largest_effect(*full, homogeneous[i], loads);
    r.tried.emplace_back(kinds[i], effect);
    if (effect <= budget && (r.kind == "none" || effect < r.estimated_effect)) {
      r.body = homogeneous[i];
      r.kind = kinds[i];
      r.estimated_effect = effect;
    }
  }
  if (r.kind == "none") {
    // Merge pairs while the merged body stays within the budget (effects against the given
    // body, not the previous step: they do not add up unchecked).
    for (Trial t = best_merge(*full, stack, loads); t.effect <= budget;
         t = best_merge(*full, t.body, loads)) {
      r.tried.emplace_back("merged", t.effect);
      r.body = t.body;
      r.kind = "merged";
      r.estimated_effect = t.effect;
      if (t.body.is_homogeneous()) break;
    }
  }
  r.why = describe(r, budget);
  return r;
}

}  // namespace coatfft
