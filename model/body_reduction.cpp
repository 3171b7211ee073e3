#include "model/body_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

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

// The panels of the integral in t = k a: half-periods of P up to t_exact, then doubling.
std::vector<std::pair<double, double>> panels() {
  std::vector<std::pair<double, double>> p;
  for (double t = 0.0; t < t_exact; t += pi / 2) p.emplace_back(t, std::min(t + pi / 2, t_exact));
  for (double t = t_exact; t < t_end; t *= 2) p.emplace_back(t, std::min(2 * t, t_end));
  return p;
}

}  // namespace

namespace {

// 2 pi u(0) = \int H P k dk of `full` under `load`: the bound's denominator.
double centre_integral(const Frf& full, const ReferenceLoad& load) {
  COATFFT_REQUIRE(std::isfinite(load.radius) && load.radius > 0,
                  "reduction_effect: radius = ", load.radius, " m, but it must be finite and > 0");
  const double u0 = 2 * pi * hankel_displacement(full, load.shape, 1.0, load.radius, 0.0, 1e-8);
  COATFFT_REQUIRE(std::isfinite(u0) && u0 > 0, "reduction_effect: u(0) = ", u0, " for FRF '",
                  full.name(), "'");
  return u0;
}

// reduction_effect with its denominator `u0` (centre_integral) given.
double effect_bound(const Frf& full, const Frf& reduced, const ReferenceLoad& load, double u0,
                    double stop_above) {
  const GslHandlerOff quiet;
  const GslWorkspace ws = make_gsl_workspace(200);
  const double a = load.radius;
  const auto dh = [&](double k) { return std::abs(full(k) - reduced(k)); };
  const auto exact = [&](double k) {
    return dh(k) * std::abs(axisymmetric_load_transform(load.shape, 1.0, a, k)) * k;
  };
  const auto envelope = [&](double k) { return dh(k) * load_envelope(load, k) * k; };
  const double abs_tol = 1e-8 * u0;
  double diff = 0.0;
  for (const auto& [t0, t1] : panels()) {
    diff += t1 <= t_exact ? integrate(exact, t0 / a, t1 / a, abs_tol, ws.get())
                          : integrate(envelope, t0 / a, t1 / a, abs_tol, ws.get());
    // The integrand is >= 0: a partial sum above stop_above settles the comparison.
    if (reference_margin * diff / u0 > stop_above) return reference_margin * diff / u0;
  }
  // Beyond t_end, k |dH| is at its limit |Cinf_full - Cinf_reduced| (the layers' exponential
  // terms are e^-(k h) small there unless a layer is thinner than a / 1e6); the larger of the
  // limit and the last value bounds it.
  const double k_end = t_end / a;
  const double kdh = std::max(k_end * dh(k_end), std::abs(full.c_inf() - reduced.c_inf()));
  diff += tail_bound(load, kdh);
  COATFFT_REQUIRE(std::isfinite(diff), "reduction_effect: the bound is not finite for FRFs '",
                  full.name(), "' and '", reduced.name(), "'");
  return reference_margin * diff / u0;
}

}  // namespace

double reduction_effect(const Frf& full, const Frf& reduced, const ReferenceLoad& load,
                        double stop_above) {
  return effect_bound(full, reduced, load, centre_integral(full, load), stop_above);
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

// The largest effect over `loads`; above `budget`, only a lower bound above it (the bound's
// integral stops there: the reduction is refused either way).
struct Reference {
  const Frf& full;
  const std::vector<ReferenceLoad>& loads;
  std::vector<double> u0;  // centre_integral of each load, computed once
  double budget;
};

double largest_effect(const Reference& ref, const LayerStack& reduced) {
  const std::unique_ptr<Frf> frf = make_frf(reduced);
  double effect = 0.0;
  for (std::size_t i = 0; i < ref.loads.size() && effect <= ref.budget; ++i)
    effect = std::max(effect, effect_bound(ref.full, *frf, ref.loads[i], ref.u0[i], ref.budget));
  return effect;
}

// The merge of one pair of `current` with the smallest effect on `full`.
Trial best_merge(const Reference& ref, const LayerStack& current) {
  Trial best{current, std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < current.coatings().size(); ++i) {
    LayerStack candidate = merged(current, i);
    const double effect = largest_effect(ref, candidate);
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
  Reference ref{*full, loads, {}, budget};
  for (const ReferenceLoad& load : loads) ref.u0.push_back(centre_integral(*full, load));
  // Homogeneous bodies first: Love's exact DC-FFT then applies.
  const LayerStack homogeneous[2] = {LayerStack(stack.substrate()),
                                     LayerStack(stack.coatings().front().material)};
  const char* kinds[2] = {"substrate", "top_half_space"};
  for (int i = 0; i < 2; ++i) {
    const double effect = largest_effect(ref, homogeneous[i]);
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
    for (Trial t = best_merge(ref, stack); t.effect <= budget; t = best_merge(ref, t.body)) {
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
