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
#include "core/detail/gsl_quadrature.hpp"
#include "core/error.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

// Below t = k a = t_exact the integrands are integrated as they are (oscillating, over panels
// of one half-period); beyond, |P| is replaced by its envelope, which is smooth (panels doubling
// in k); beyond t_end the tail is bounded analytically.
constexpr double t_exact = 200.0;
constexpr double t_end = 1e8;
constexpr double kReferenceRelTol = 1e-4;
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

// Each panel to kReferenceRelTol of itself or `abs_tol` (a small fraction of u(0): the panels where
// the FRFs agree to rounding need not be resolved).
double integrate(const std::function<double(double)>& f, double a, double b, double abs_tol,
                 gsl_integration_workspace* ws) {
  return detail::gsl_qag(f, a, b, abs_tol, kReferenceRelTol, GSL_INTEG_GAUSS21, ws).value;
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
  const detail::GslHandlerOff quiet;
  const detail::GslWorkspace ws = detail::make_gsl_workspace(200);
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

// The closed-form bound (docs/auto.md, section 2). With P = 2 pi a^2 Phi(k a) and g(k) =
// |k H(k) - C_sub| (C_sub = k H_sub = c0, the substrate's 2/E*), the numerator of the effect
// bound is 2 pi a \int g(s/a) |Phi(s)| ds and the substrate's 2 pi u(0) is 2 pi a C_sub I, I =
// \int Phi ds (pi/4 for Hertz, 1 for the disk: Johnson 1985, 3.4 and 3.9).
constexpr double nodes_per_octave = 4.0;
constexpr double max_octaves = 1000.0;  // caps the nodes at 4001 for any input
// sqrt(J1(1)^2 + Y1(1)^2): x (J1^2 + Y1^2) decreases for x > 0 (Watson 1944, 13.74), so |J1(x)|
// <= 0.8967 / sqrt(x) for x >= 1.
constexpr double j1_envelope = 0.8967;

// max |Phi|: |j1(s)/s| <= 1/3 and |J1(s)/s| <= 1/2.
double shape_peak(AxisymmetricLoad shape) {
  return shape == AxisymmetricLoad::hertz ? 1.0 / 3.0 : 0.5;
}

double shape_integral(AxisymmetricLoad shape) {
  return shape == AxisymmetricLoad::hertz ? pi / 4 : 1.0;
}

// \int_s0^s1 (s1 may be inf) of the decay of |Phi| for s >= 1: Hertz |sin s - s cos s| / s^3 <=
// (1 + s)/s^3, the disk j1_envelope s^-3/2.
double decay_integral(AxisymmetricLoad shape, double s0, double s1) {
  if (shape == AxisymmetricLoad::hertz) {
    const auto F = [](double s) { return std::isinf(s) ? 0.0 : -0.5 / (s * s) - 1.0 / s; };
    return F(s1) - F(s0);
  }
  const auto F = [](double s) { return std::isinf(s) ? 0.0 : -2 * j1_envelope / std::sqrt(s); };
  return F(s1) - F(s0);
}

// A bound of \int_s0^s1 |Phi| ds: the peak below s = 1, the decay above, or the peak throughout.
double shape_bin(AxisymmetricLoad shape, double s0, double s1) {
  const double peak = shape_peak(shape);
  double envelope = peak * std::max(0.0, std::min(s1, 1.0) - s0);
  if (s1 > 1.0) envelope += decay_integral(shape, std::max(s0, 1.0), s1);
  return std::isinf(s1) ? envelope : std::min(envelope, peak * (s1 - s0));
}

// \int g(s/a) |Phi(s)| ds bounded from g sampled at nodes_per_octave wavenumbers an octave, from
// 1e-3 / max(a, h_total) (where g grows like k h: C - C(0) = O(kh), docs/theory.md 2.6(b)) to
// max(64 / h_min, 1e3 / a) (beyond, every layer's exp(-2 k h) < 1e-55): on each bin g is taken at
// its larger end, below the first node at the first, beyond the last at the largest sample or
// |C_inf - C_sub|, the limit.
double sampled_integral(const Frf& full, const LayerStack& stack, const ReferenceLoad& load,
                        long& evaluations) {
  const double a = load.radius;
  double h_min = stack.total_thickness();
  for (const Coating& c : stack.coatings()) h_min = std::min(h_min, c.thickness);
  const double log_lo = std::log2(1e-3) - std::log2(std::max(a, stack.total_thickness()));
  const double log_hi = std::max(std::log2(64.0) - std::log2(h_min), std::log2(1e3 / a));
  const double octaves = std::min(log_hi - log_lo, max_octaves);
  const auto nodes = static_cast<long>(std::ceil(octaves * nodes_per_octave));
  const double c_sub = full.c0();
  const auto g = [&](double k) {
    ++evaluations;
    return std::abs(k * full(k) - c_sub);
  };
  double k = std::exp2(log_lo);
  double g_k = g(k);
  double g_max = g_k;
  double sum = g_k * shape_bin(load.shape, 0.0, k * a);
  for (long j = 1; j <= nodes; ++j) {
    const double k_next = std::exp2(log_lo + static_cast<double>(j) / nodes_per_octave);
    const double g_next = g(k_next);
    sum += std::max(g_k, g_next) * shape_bin(load.shape, k * a, k_next * a);
    k = k_next;
    g_k = g_next;
    g_max = std::max(g_max, g_k);
  }
  const double g_tail = std::max(g_max, std::abs(full.c_inf() - c_sub));
  return sum + g_tail * shape_bin(load.shape, k * a, std::numeric_limits<double>::infinity());
}

// The closed-form bound with the lower bound of 2 pi u(0) it rests on (<= 0: none).
struct ClosedFormBound {
  double effect = 0.0;
  double centre_lower = 0.0;
};

ClosedFormBound closed_form_bound(const Frf& full, const LayerStack& stack,
                                  const ReferenceLoad& load, long& evaluations) {
  COATFFT_REQUIRE(std::isfinite(load.radius) && load.radius > 0,
                  "substrate_effect_bound: radius = ", load.radius,
                  " m, but it must be finite and > 0");
  const double numerator = sampled_integral(full, stack, load, evaluations);
  const double substrate_centre = full.c0() * shape_integral(load.shape);
  // u(0) >= u_sub(0) - (1/2 pi) \int |H - H_sub| |P| k dk: the same numerator.
  const double lower = substrate_centre - numerator;
  const double effect =
      lower > 0 ? reference_margin * numerator / lower : std::numeric_limits<double>::infinity();
  return {effect, 2 * pi * load.radius * lower};
}

}  // namespace

double substrate_effect_bound(const LayerStack& stack, const ReferenceLoad& load,
                              long* evaluations) {
  if (stack.is_homogeneous()) return 0.0;
  long count = 0;
  const double effect = closed_form_bound(*make_frf(stack), stack, load, count).effect;
  if (evaluations != nullptr) *evaluations += count;
  return effect;
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

// An FRF that counts its evaluations into `count` (ReductionWork::frf_evaluations).
class CountedFrf final : public Frf {
 public:
  CountedFrf(std::unique_ptr<Frf> frf, long& count) : frf_(std::move(frf)), count_(&count) {}
  double operator()(double k) const override {
    ++*count_;
    return (*frf_)(k);
  }
  double c0() const override { return frf_->c0(); }
  double c_inf() const override { return frf_->c_inf(); }
  std::string name() const override { return frf_->name(); }

 private:
  std::unique_ptr<Frf> frf_;
  long* count_;
};

// The largest effect over `loads`; above `budget`, only a lower bound above it (the bound's
// integral stops there: the reduction is refused either way).
struct Reference {
  const Frf& full;
  const std::vector<ReferenceLoad>& loads;
  std::vector<double> u0;  // 2 pi u(0) of each load (or a lower bound of it), computed once
  double budget;
  ReductionWork* work;
};

double largest_effect(const Reference& ref, const LayerStack& reduced) {
  const CountedFrf frf(make_frf(reduced), ref.work->frf_evaluations);
  double effect = 0.0;
  for (std::size_t i = 0; i < ref.loads.size() && effect <= ref.budget; ++i) {
    ++ref.work->quadratures;
    effect = std::max(effect, effect_bound(ref.full, frf, ref.loads[i], ref.u0[i], ref.budget));
  }
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

// Whether the Hankel references are affordable (accurate_work_limit): each takes about
// 10 a / h_top panels (hankel_displacement, split route: k H converges like (k h_top)^2
// exp(-2 k h_top), docs/theory.md 2.2, so its range ends below 32 / h_top, in panels of pi / a),
// and an evaluation of the FRF costs about in proportion to the coatings (bench/results/
// frf_eval.csv: 0.05 us for one, 0.6 us for five).
bool resolved(const LayerStack& stack, const std::vector<ReferenceLoad>& loads) {
  const double h_top = stack.coatings().front().thickness;
  const auto layers = static_cast<double>(stack.coatings().size());
  double work = 0.0;
  for (const ReferenceLoad& load : loads) work += layers * load.radius / h_top;
  return work <= accurate_work_limit;
}

// A coating far thinner than some load: the closed-form bound of the substrate. Within the
// budget it decides (true: `r` is the substrate); otherwise its lower bounds of 2 pi u(0) become
// the effect bounds' denominators.
bool decide_unresolved(const LayerStack& stack, Reference& ref, BodyReduction& r) {
  double effect = 0.0;
  long counted_by_full = 0;  // ref.full counts them into r.work already
  for (const ReferenceLoad& load : ref.loads) {
    const ClosedFormBound b = closed_form_bound(ref.full, stack, load, counted_by_full);
    effect = std::max(effect, b.effect);
    ref.u0.push_back(b.centre_lower);
  }
  if (effect > ref.budget) {
    r.tried.emplace_back("substrate (closed form)", effect);
    return false;
  }
  r.tried.emplace_back("substrate", effect);
  r.body = LayerStack(stack.substrate());
  r.kind = "substrate";
  r.estimated_effect = effect;
  return true;
}

// The homogeneous bodies (Love's exact DC-FFT then applies), then merged pairs.
void try_reductions(const LayerStack& stack, const Reference& ref, BodyReduction& r) {
  const LayerStack homogeneous[2] = {LayerStack(stack.substrate()),
                                     LayerStack(stack.coatings().front().material)};
  const char* kinds[2] = {"substrate", "top_half_space"};
  for (int i = 0; i < 2; ++i) {
    const double effect = largest_effect(ref, homogeneous[i]);
    r.tried.emplace_back(kinds[i], effect);
    if (effect <= ref.budget && (r.kind == "none" || effect < r.estimated_effect)) {
      r.body = homogeneous[i];
      r.kind = kinds[i];
      r.estimated_effect = effect;
    }
  }
  if (r.kind != "none") return;
  // Merge pairs while the merged body stays within the budget (effects against the given
  // body, not the previous step: they do not add up unchecked).
  for (Trial t = best_merge(ref, stack); t.effect <= ref.budget; t = best_merge(ref, t.body)) {
    r.tried.emplace_back("merged", t.effect);
    r.body = t.body;
    r.kind = "merged";
    r.estimated_effect = t.effect;
    if (t.body.is_homogeneous()) break;
  }
}

}  // namespace

BodyReduction reduce_body(const LayerStack& stack, const std::vector<ReferenceLoad>& loads,
                          double budget) {
  COATFFT_REQUIRE(std::isfinite(budget) && budget > 0, "reduce_body: budget = ", budget,
                  ", but it must be finite and > 0");
  COATFFT_REQUIRE(!loads.empty(), "reduce_body: no reference load");
  BodyReduction r{stack, "none", 0.0, "the body is homogeneous", {}, {}};
  if (stack.is_homogeneous()) return r;
  const CountedFrf full(make_frf(stack), r.work.frf_evaluations);
  Reference ref{full, loads, {}, budget, &r.work};
  if (resolved(stack, loads)) {
    for (const ReferenceLoad& load : loads) {
      ++r.work.quadratures;
      ref.u0.push_back(centre_integral(full, load));
    }
    try_reductions(stack, ref, r);
  } else if (decide_unresolved(stack, ref, r)) {
    r.why = describe(r, budget) +
            " (closed-form bound: the coating is far thinner than the reference loads)";
    return r;
  } else if (std::all_of(ref.u0.begin(), ref.u0.end(), [](double u) { return u > 0; })) {
    try_reductions(stack, ref, r);
  }
  r.why = describe(r, budget);
  return r;
}

}  // namespace coatfft
