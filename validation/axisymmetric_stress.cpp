#include "validation/axisymmetric_stress.hpp"

#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"

namespace coatfft {

namespace {

using std::numbers::pi;

// The six fields in the order of AxisymmetricStress; the first four are stresses.
constexpr int kFields = 6;
constexpr int kStresses = 4;
using Fields = std::array<double, kFields>;

// The 15-point Kronrod rule and its embedded 7-point Gauss rule on [-1, 1] (Piessens et al. 1983,
// QUADPACK's qk15): nodes +-xgk[j], xgk[7] = 0; the Gauss nodes are the odd j.
constexpr std::array<double, 8> kXgk{
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kWgk{
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kWg{
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Problem {
  const LayerModes& modes;
  AxisymmetricLoad load;
  double amplitude, a;
  std::span<const double> r, z;
  InterfaceSide side;
};

// J0(x), J1(x) and J1(x)/x; the series below 1e-4 (next terms < 1e-18 relative) also keeps GSL's
// underflow handling away from tiny x.
struct Bessel {
  double j0, j1, j1x;
};
Bessel bessel(double x) {
  if (x < 1e-4) {
    const double x2 = x * x;
    return {1.0 - 0.25 * x2, 0.5 * x - x2 * x / 16.0, 0.5 - x2 / 16.0};
  }
  const double j1 = gsl_sf_bessel_J1(x);
  return {gsl_sf_bessel_J0(x), j1, j1 / x};
}

// The six integrands at wavenumber k for every (depth, radius), point-major: f[point][field], and
// in `size` the magnitude of the terms each is formed from (the largest stress or displacement
// coefficient of the point times the common factor: LayerModes is accurate relative to it, and
// sigma_rr, sigma_tt are differences of such terms). The common factor P^(k) k / (2 pi) turns
// the mode coefficients per unit pressure into the Hankel integrands of the header.
void integrands(const Problem& pb, double k, std::vector<Bessel>& bes, std::vector<Fields>& f,
                std::vector<Fields>& size) {
  const std::vector<ModeFields> m = pb.modes.at(k, pb.z, pb.side);
  const double w = axisymmetric_load_transform(pb.load, pb.amplitude, pb.a, k) * k / (2.0 * pi);
  for (std::size_t ir = 0; ir < pb.r.size(); ++ir) bes[ir] = bessel(k * pb.r[ir]);
  for (std::size_t iz = 0; iz < pb.z.size(); ++iz) {
    const ModeFields& q = m[iz];
    const double delta = q.sLL_p - q.sTT_p;
    const double ss = std::abs(w) * std::max({std::abs(q.szz_p), std::abs(q.sLz_p),
                                              std::abs(q.sLL_p), std::abs(q.sTT_p)});
    const double su = std::abs(w) * std::max(std::abs(q.uL_p), std::abs(q.uz_p));
    for (std::size_t ir = 0; ir < pb.r.size(); ++ir) {
      const Bessel& b = bes[ir];
      const std::size_t p = iz * pb.r.size() + ir;
      f[p] = {w * (q.sLL_p * b.j0 - delta * b.j1x),
              w * (q.sTT_p * b.j0 + delta * b.j1x),
              w * q.szz_p * b.j0,
              -w * q.sLz_p * b.j1,
              -w * q.uL_p * b.j1,
              w * q.uz_p * b.j0};
      size[p] = {ss, ss, ss, ss, su, su};
    }
  }
}

// Sums of one panel for every point and field: Kronrod, Gauss, and Kronrod of the terms'
// magnitudes (the scale of the rounding in the panel's sums).
struct PanelSums {
  std::vector<Fields> kronrod, gauss, magnitude;
  std::vector<Fields> f, size;  // scratch: the integrands at one node
  std::vector<Bessel> bes;
};

void panel(const Problem& pb, double lo, double hi, PanelSums& s) {
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  const Fields zero{};
  std::fill(s.kronrod.begin(), s.kronrod.end(), zero);
  std::fill(s.gauss.begin(), s.gauss.end(), zero);
  std::fill(s.magnitude.begin(), s.magnitude.end(), zero);
  for (int j = 0; j < 15; ++j) {
    const int idx = j < 8 ? j : 14 - j;  // nodes -xgk[0..7], then +xgk[6..0]
    const double x = j < 8 ? -kXgk[idx] : kXgk[idx];
    const double wk = half * kWgk[idx];
    const double wg = idx % 2 == 1 ? half * kWg[idx / 2] : 0.0;
    integrands(pb, mid + half * x, s.bes, s.f, s.size);
    for (std::size_t p = 0; p < s.f.size(); ++p) {
      for (int c = 0; c < kFields; ++c) {
        s.kronrod[p][c] += wk * s.f[p][c];
        s.gauss[p][c] += wg * s.f[p][c];
        s.magnitude[p][c] += wk * s.size[p][c];
      }
    }
  }
}

// Whether the panel's Kronrod sums meet `budget` (absolute, per field): the Kronrod-Gauss
// difference, an upper bound of the Gauss rule's error and far above the Kronrod rule's, less the
// rounding the sums cannot avoid.
bool accepted(const PanelSums& s, const Fields& budget) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (std::size_t p = 0; p < s.kronrod.size(); ++p) {
    for (int c = 0; c < kFields; ++c) {
      const double err = std::abs(s.kronrod[p][c] - s.gauss[p][c]);
      if (err > budget[c] + 100.0 * eps * s.magnitude[p][c]) return false;
    }
  }
  return true;
}

// \int_lo^hi of every integrand to the absolute error budget * (hi - lo) (per field), bisecting
// the interval where the panel rule does not meet its share; adds into `total`.
void integrate_interval(const Problem& pb, double lo, double hi, const Fields& budget_per_k,
                        PanelSums& s, std::vector<Fields>& total) {
  constexpr int kMaxDepth = 24;
  struct Piece {
    double lo, hi;
    int depth;
  };
  std::vector<Piece> todo{{lo, hi, 0}};
  while (!todo.empty()) {
    const Piece piece = todo.back();
    todo.pop_back();
    panel(pb, piece.lo, piece.hi, s);
    Fields budget;
    for (int c = 0; c < kFields; ++c) budget[c] = budget_per_k[c] * (piece.hi - piece.lo);
    if (!accepted(s, budget)) {
      if (piece.depth == kMaxDepth) {
        throw Error(detail::concat("axisymmetric_stress: quadrature on [", piece.lo, ", ", piece.hi,
                                   "] rad/m does not converge"));
      }
      const double mid = 0.5 * (piece.lo + piece.hi);
      todo.push_back({piece.lo, mid, piece.depth + 1});
      todo.push_back({mid, piece.hi, piece.depth + 1});
      continue;
    }
    for (std::size_t p = 0; p < total.size(); ++p) {
      for (int c = 0; c < kFields; ++c) total[p][c] += s.kronrod[p][c];
    }
  }
}

// The integration range: every integrand carries exp(-k z) times at most (1 + kz)^2 (the
// homogeneous field of docs/theory.md 2.7; in a stack the reflections add exp(-k(2h - z)) <=
// exp(-kz) with polynomial factors in k h), and the load transform decays like (ka)^(-3/2). The
// tail beyond X = k z is then ~ sqrt(a/z) X^(3/2) exp(-X) of the amplitude; X = L + 3 ln L + 8
// keeps it below 1e-2 rel_tol with a margin for the stack's factors.
double wavenumber_limit(double a, double z_min, double rel_tol) {
  const double L = std::log(100.0 * std::max(1.0, std::sqrt(a / z_min)) / rel_tol);
  return (L + 3.0 * std::log(L) + 8.0) / z_min;
}

// Panels no wider than a quarter period of J(kr) times the load transform (frequency r + a in k),
// 1/(4 h_min) (the stack's coefficients vary on the scale of its thinnest coating) and 1/z.
double panel_width(const LayerStack& stack, double a, double r_max, double z_min) {
  double width = std::min(pi / (2.0 * (r_max + a)), 1.0 / z_min);
  for (const Coating& c : stack.coatings()) width = std::min(width, 0.25 / c.thickness);
  return width;
}

double softest_shear_modulus(const LayerStack& stack) {
  double mu = stack.substrate().shear_modulus();
  for (const Coating& c : stack.coatings()) mu = std::min(mu, c.material.shear_modulus());
  return mu;
}

void check_arguments(double amplitude, double a, std::span<const double> r,
                     std::span<const double> z, double rel_tol) {
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "axisymmetric_stress: a = ", a,
                  " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(amplitude), "axisymmetric_stress: amplitude = ", amplitude,
                  " Pa, but it must be finite");
  COATFFT_REQUIRE(rel_tol >= 1e-14 && rel_tol < 1e-2, "axisymmetric_stress: rel_tol = ", rel_tol,
                  ", but it must lie in [1e-14, 1e-2)");
  for (double ri : r) {
    COATFFT_REQUIRE(std::isfinite(ri) && ri >= 0, "axisymmetric_stress: r = ", ri,
                    " m, but r must be finite and >= 0");
  }
  for (double zi : z) {
    COATFFT_REQUIRE(std::isfinite(zi) && zi > 0, "axisymmetric_stress: z = ", zi,
                    " m, but z must be finite and > 0 (the surface z = 0 is not supported)");
  }
}

}  // namespace

std::vector<AxisymmetricStress> axisymmetric_stress_grid(const LayerStack& stack,
                                                         AxisymmetricLoad load, double amplitude,
                                                         double a, std::span<const double> r,
                                                         std::span<const double> z,
                                                         InterfaceSide side, double rel_tol) {
  check_arguments(amplitude, a, r, z, rel_tol);
  const std::size_t points = r.size() * z.size();
  std::vector<AxisymmetricStress> out(points, AxisymmetricStress{0, 0, 0, 0, 0, 0});
  if (points == 0 || amplitude == 0.0) return out;
  const LayerModes modes(stack);
  const Problem pb{modes, load, amplitude, a, r, z, side};
  const double r_max = *std::max_element(r.begin(), r.end());
  const double z_min = *std::min_element(z.begin(), z.end());
  const double k_max = wavenumber_limit(a, z_min, rel_tol);
  const auto panels = static_cast<long>(std::ceil(k_max / panel_width(stack, a, r_max, z_min)));
  const double width = k_max / static_cast<double>(panels);
  // Error budget per unit of k: rel_tol of the stress and displacement scales over [0, k_max].
  const double stress = std::abs(amplitude),
               displacement = stress * a / softest_shear_modulus(stack);
  Fields budget_per_k;
  for (int c = 0; c < kFields; ++c) {
    budget_per_k[c] = rel_tol * (c < kStresses ? stress : displacement) / k_max;
  }
  PanelSums sums{std::vector<Fields>(points), std::vector<Fields>(points),
                 std::vector<Fields>(points), std::vector<Fields>(points),
                 std::vector<Fields>(points), std::vector<Bessel>(r.size())};
  std::vector<Fields> total(points, Fields{});
  for (long i = 0; i < panels; ++i) {
    const double lo = static_cast<double>(i) * width;
    integrate_interval(pb, lo, i + 1 == panels ? k_max : lo + width, budget_per_k, sums, total);
  }
  for (std::size_t p = 0; p < points; ++p) {
    const Fields& t = total[p];
    out[p] = {t[0], t[1], t[2], t[3], t[4], t[5]};
  }
  return out;
}

std::vector<AxisymmetricStress> axisymmetric_stress_at(const LayerStack& stack,
                                                       AxisymmetricLoad load, double amplitude,
                                                       double a, std::span<const double> r,
                                                       double z, InterfaceSide side,
                                                       double rel_tol) {
  return axisymmetric_stress_grid(stack, load, amplitude, a, r, {&z, 1}, side, rel_tol);
}

AxisymmetricStress axisymmetric_stress(const LayerStack& stack, AxisymmetricLoad load,
                                       double amplitude, double a, double r, double z,
                                       InterfaceSide side, double rel_tol) {
  return axisymmetric_stress_grid(stack, load, amplitude, a, {&r, 1}, {&z, 1}, side, rel_tol)[0];
}

}  // namespace coatfft
