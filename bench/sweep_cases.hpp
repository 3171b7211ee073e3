#pragma once
// The test problems of the speed-against-error sweep (bench_sweep, bench_sweep_row, bench_figures,
// bench_reference_check) and their reference displacements: a Hertz pressure (p0 = 1 GPa,
// a = 1 mm) on [-1.5a, 1.5a]^2 over a homogeneous steel half-space (closed form, docs/theory.md
// 1.4) and over four bonded coatings on steel (continuous Hankel-transform reference).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/detail/lagrange.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/types.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/sampling.hpp"
#include "materials/material.hpp"
#include "validation/hankel_displacement.hpp"
#include "validation/hertz.hpp"

namespace coatfft::sweep {

/// One body under the Hertz load, with the sampling of the load used by every method.
struct SweepCase {
  std::string name;
  std::string description;
  std::string reference;  ///< how u_ref is obtained (for the CSV header)
  LayerStack stack;
  Sampling sampling;
  double p0 = 1e9;             ///< Hertz peak pressure [Pa]
  double a = 1e-3;             ///< contact radius [m]
  double half_width = 1.5e-3;  ///< the domain is [-half_width, half_width]^2 [m]
};

inline Material steel() {
  return Material(210e9, 0.3);
}

inline SweepCase coated_case(const std::string& name, double modulus_ratio, double h_over_a) {
  const double a = 1e-3;
  const Material coating(modulus_ratio * steel().youngs_modulus(), 0.3);
  SweepCase c{name,
              "bonded coating E_c/E_s = " + std::to_string(modulus_ratio).substr(0, 4) +
                  ", nu = 0.3, h/a = " + std::to_string(h_over_a).substr(0, 3) +
                  " on steel (210 GPa, 0.3), pressure sampled as cell averages",
              "continuous Hankel transform of H(k) times the Hertz load's transform at the "
              "cell centres",
              LayerStack({Coating{coating, h_over_a * a, Interface::bonded}}, steel()),
              Sampling::cell_average};
  return c;
}

/// Every case, homogeneous first.
inline std::vector<SweepCase> all_cases() {
  std::vector<SweepCase> cases;
  cases.push_back({"hertz_homogeneous",
                   "steel half-space (210 GPa, 0.3), pressure sampled at cell centres (as in "
                   "Spinu 2021)",
                   "closed form hertz_displacement (docs/theory.md 1.6-1.7)", LayerStack(steel()),
                   Sampling::centre});
  cases.push_back(coated_case("coated_soft_h0.1", 0.1, 0.1));
  cases.push_back(coated_case("coated_soft_h1", 0.1, 1.0));
  cases.push_back(coated_case("coated_hard_h0.1", 10.0, 0.1));
  cases.push_back(coated_case("coated_hard_h1", 10.0, 1.0));
  return cases;
}

/// The case called `name`; throws InvalidArgument listing the names when there is none.
inline SweepCase find_case(const std::string& name) {
  std::string names;
  for (const SweepCase& c : all_cases()) {
    if (c.name == name) return c;
    names += " " + c.name;
  }
  throw InvalidArgument("bench_sweep: unknown case '" + name + "'; known:" + names);
}

/// The N x N grid of a case.
inline Grid case_grid(const SweepCase& c, std::ptrdiff_t n) {
  return Grid(n, n, 2.0 * c.half_width, 2.0 * c.half_width);
}

inline const char* to_string(Sampling s) {
  return s == Sampling::centre ? "centre" : "cell_average";
}

/// Numbers as the sweep's CSVs write them: 6 significant digits.
inline std::string fmt(double v) {
  std::ostringstream os;
  os << std::setprecision(6) << v;
  return os.str();
}

/// Relative tolerance of the Hankel reference of the coated cases.
inline constexpr double reference_tolerance = 1e-10;

/// u_ref at every cell centre [m] and at r = 0 [m] (the normalisation of Spinu 2021).
struct Reference {
  Field u;
  double u_centre = 0.0;
};

/// Evaluates the radial function `f(r)` at every cell centre of the square grid `grid`, once per
/// distinct radius: with dx = dy the centres lie at (dx/2) (2i + 1 - n) along each axis, so
/// r^2 = (dx/2)^2 s with the integer s = (2i + 1 - n)^2 + (2j + 1 - n)^2. The distinct radii
/// (about n^2/8) are shared out among `threads` threads.
inline Field radial_field(const Grid& grid, const std::function<double(double)>& f,
                          int threads = 2) {
  COATFFT_REQUIRE(grid.nx() == grid.ny() && grid.lx() == grid.ly(),
                  "radial_field: the grid must be square, got ", grid.nx(), " x ", grid.ny());
  const std::ptrdiff_t n = grid.nx();
  auto key = [n](std::ptrdiff_t i, std::ptrdiff_t j) {
    const std::int64_t a = 2 * i + 1 - n;
    const std::int64_t b = 2 * j + 1 - n;
    return a * a + b * b;
  };
  std::vector<std::int64_t> keys;
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (2 * i + 1 >= n && 2 * j + 1 >= n && i >= j) keys.push_back(key(i, j));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<double> values(keys.size());
  const double half = 0.5 * grid.dx();
  detail::parallel_for(0, static_cast<std::ptrdiff_t>(keys.size()), threads, [&](std::ptrdiff_t q) {
    const auto k = static_cast<std::size_t>(q);
    values[k] = f(half * std::sqrt(static_cast<double>(keys[k])));
  });
  Field u(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const auto it = std::lower_bound(keys.begin(), keys.end(), key(i, j));
      u(i, j) = values[static_cast<std::size_t>(it - keys.begin())];
    }
  return u;
}

/// u_ref(r) [m] of a case for 0 <= r <= r_max. Homogeneous: the closed form. Coated: the Hankel
/// reference (relative tolerance `reference_tolerance`) is split as u = u_top + w, u_top the
/// closed form for a half-space of the top layer's modulus (E* = 2 / c_inf, docs/theory.md 1.4) and
/// w the part of the remainder H - c_inf/k, which decays like exp(-2 k h) in k, so w is smooth in r
/// on the scale h: w is tabulated once on nodes dr = min(h, a)/50 and interpolated with 6-point
/// Lagrange (w is even in r: nodes mirror at 0); u_top, which carries the r = a kink, stays exact.
/// About (r_max / dr) Hankel evaluations instead of one per distinct cell radius (n^2/8).
class RadialReference {
 public:
  RadialReference(const SweepCase& c, double r_max, int threads = 2)
      : p0_(c.p0), a_(c.a), frf_(make_frf(c.stack)) {
    e_top_ = 2.0 / frf_->c_inf();
    if (c.stack.is_homogeneous()) return;
    const double h = c.stack.coatings().front().thickness;
    dr_ = std::min(h, c.a) / 50.0;
    const auto nodes = static_cast<std::ptrdiff_t>(std::ceil(r_max / dr_)) + 4;
    w_.resize(static_cast<std::size_t>(nodes));
    detail::parallel_for(0, nodes, threads, [&](std::ptrdiff_t q) {
      w_[static_cast<std::size_t>(q)] = exact_remainder(dr_ * static_cast<double>(q));
    });
  }

  /// u_ref(r) [m] from the table (coated) or the closed form (homogeneous).
  double operator()(double r) const { return top(r) + remainder(r); }
  /// u_ref(r) [m] by a fresh Hankel evaluation at `tol` by `route` (no table).
  double exact(double r, double tol = reference_tolerance,
               HankelRoute route = HankelRoute::split) const {
    return hankel_displacement(*frf_, AxisymmetricLoad::hertz, p0_, a_, r, tol, route);
  }
  /// Spacing of the remainder table [m] (0: homogeneous, no table).
  double node_spacing() const { return dr_; }
  std::size_t nb_nodes() const { return w_.size(); }

 private:
  double top(double r) const { return hertz_displacement(r, p0_, a_, e_top_); }
  double exact_remainder(double r) const { return exact(r) - top(r); }
  double remainder(double r) const {
    if (w_.empty()) return 0.0;
    const double t = r / dr_;
    const double floor_t = std::floor(t);
    const auto base = static_cast<std::ptrdiff_t>(floor_t) - 2;  // nodes base..base+5
    COATFFT_REQUIRE(base + 5 < static_cast<std::ptrdiff_t>(w_.size()), "RadialReference: r = ", r,
                    " beyond the table");
    std::array<double, 6> f{};
    for (std::ptrdiff_t m = 0; m < 6; ++m)
      f[static_cast<std::size_t>(m)] = w_[static_cast<std::size_t>(std::abs(base + m))];
    return detail::lagrange6(f.data(), t - floor_t);
  }

  double p0_;
  double a_;
  std::unique_ptr<Frf> frf_;
  double e_top_ = 0.0;
  double dr_ = 0.0;
  std::vector<double> w_;
};

/// The largest cell-centre radius of a case's grids [m] (the domain's half diagonal).
inline double max_radius(const SweepCase& c) {
  return std::sqrt(2.0) * c.half_width;
}

/// The reference displacement of case `c` on `grid`, from the radial reference `u_ref`.
inline Reference reference(const RadialReference& u_ref, const Grid& grid) {
  Reference ref;
  ref.u = radial_field(grid, [&](double r) { return u_ref(r); });
  ref.u_centre = u_ref(0.0);
  return ref;
}

/// As above, building the radial reference of `c` first.
inline Reference reference(const SweepCase& c, const Grid& grid) {
  return reference(RadialReference(c, max_radius(c)), grid);
}

}  // namespace coatfft::sweep
