// The surface response of layered bodies to pressure and tangential tractions
// (frf/traction_response.hpp, convolution/kernels/lattice_coefficients.hpp,
// convolution/kernels/traction_kernels.hpp, validation/axisymmetric_traction.hpp) against
// independent references: the homogeneous closed forms (Johnson 1985), the coated FRF of frf/
// (closed form), Gaussian spectra with closed-form Hankel transforms, a coating of the substrate's
// own material, and the continuous Hankel reference of coated bodies under a Hertz-type traction
// and pressure.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "convolution/kernels/lattice_coefficients.hpp"
#include "convolution/kernels/traction_kernels.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "core/detail/gauss_legendre.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/traction_response.hpp"
#include "loads/hertz_pressure.hpp"
#include "validation/axisymmetric_traction.hpp"
#include "validation/hertz.hpp"

using namespace coatfft;

namespace {

using std::numbers::pi;
const Material substrate(100e9, 0.3);

LayerStack coated(double e_ratio, double h) {
  return LayerStack({Coating{Material(e_ratio * 100e9, 0.25), h, Interface::bonded}}, substrate);
}

// The cell integral of a smooth point kernel by an 8 x 8 Gauss-Legendre rule (the kernels below
// vary on >= 3 cells: converged to ~1e-15 relative).
template <class F>
double cell_integral(F kernel, double x, double y, double dx, double dy) {
  const auto& rule = detail::gauss_legendre<8>();
  double s = 0.0;
  for (int p = 0; p < 8; ++p)
    for (int q = 0; q < 8; ++q)
      s += rule.weights[p] * rule.weights[q] *
           kernel(x - 0.5 * dx * rule.nodes[p], y - 0.5 * dy * rule.nodes[q]);
  return 0.25 * dx * dy * s;
}

}  // namespace

TEST_CASE("surface FRFs: the half-space's closed forms and the coated Frf", "[traction_kernels]") {
  // Homogeneous: k f(k) is Johnson's (1985) constants at every k (LayerModes against the closed
  // forms of half_space_traction_frfs: two independent derivations).
  const TractionResponse half(LayerStack{substrate});
  const TractionFrfs c = half_space_traction_frfs(substrate);
  for (double k : {1e-3, 1.0, 1e3, 1e6}) {
    const TractionFrfs f = half(k);
    CHECK(k * f.zz == Approx(c.zz).epsilon(1e-14));
    CHECK(k * f.s == Approx(c.s).epsilon(1e-14));
    CHECK(k * f.d == Approx(c.d).epsilon(1e-14));
    CHECK(k * f.c == Approx(c.c).epsilon(1e-14));
  }
  // H_zz = S + D for a half-space: u_z under p equals u_L under q_L (docs/theory.md (2.9.1)).
  CHECK(c.zz == Approx(c.s + c.d).epsilon(1e-15));
  // Coated: H_zz is the closed-form coated FRF; the limits are the substrate's and coating's.
  const LayerStack body = coated(10.0, 1e-4);
  const TractionResponse response(body);
  const auto frf = make_frf(body);
  for (double k : {1e1, 1e3, 1e4, 1e5}) CHECK(response(k).zz == Approx((*frf)(k)).epsilon(1e-13));
  const double h = 1e-4;
  const TractionFrfs low = response(1e-9 / h), high = response(1e4 / h);
  const TractionFrfs f0 = response.at_zero(), fi = response.at_infinity();
  // k f = f0 (1 + b k h + ...), |b| <= 17 for this stiff coating: 1.7e-8 at k h = 1e-9.
  CHECK(1e-9 / h * low.s == Approx(f0.s).epsilon(1e-7));
  CHECK(1e-9 / h * low.d == Approx(f0.d).epsilon(1e-7));
  CHECK(1e-9 / h * low.c == Approx(f0.c).epsilon(1e-7));
  CHECK(1e4 / h * high.s == Approx(fi.s).epsilon(1e-12));
  CHECK(1e4 / h * high.d == Approx(fi.d).epsilon(1e-12));
  CHECK(1e4 / h * high.c == Approx(fi.c).epsilon(1e-12));
  CHECK(response.bonded());
  CHECK_FALSE(
      TractionResponse(LayerStack({Coating{substrate, h, Interface::frictionless}}, substrate))
          .bonded());
  CHECK_THROWS_AS(response(0.0), InvalidArgument);
}

TEST_CASE("lattice coefficients of Gaussian spectra equal their closed-form kernels",
          "[traction_kernels]") {
  // F = k^2 exp(-s k^2) cos 2theta and -i k exp(-s k^2) cos theta have the kernels
  //   -cos 2phi r^2 exp(-r^2/(4 s)) / (16 pi s^3),  cos phi r exp(-r^2/(4 s)) / (8 pi s^2)
  // (\int x^(n+1) exp(-s x^2) J_n(b x) dx = b^n/(2 s)^(n+1) exp(-b^2/(4 s))). With sqrt(s) = 2
  // cells they are smooth on the cells, and their periodic images (>= 15 sqrt(s) away) negligible.
  const Grid g(40, 30, 40e-3, 30e-3);
  const double s = std::pow(2.0 * g.dx(), 2);
  LatticeSpectra spectra;
  spectra.parity = {{false, false}, {true, false}};
  spectra.k_cut = std::sqrt(40.0 / s);
  spectra.sample = [s](double kx, double ky, double k, std::span<double> out) {
    const double c = kx / k, sn = ky / k, e = std::exp(-s * k * k);
    out[0] = k * k * e * (c * c - sn * sn);
    out[1] = k * e * c;  // i F
  };
  const auto cos2 = [s](double x, double y) {
    return (y * y - x * x) * std::exp(-(x * x + y * y) / (4 * s)) / (16 * pi * s * s * s);
  };
  const auto cos1 = [s](double x, double y) {
    return x * std::exp(-(x * x + y * y) / (4 * s)) / (8 * pi * s * s);
  };
  for (int alpha : {2, 16}) {
    LatticeOptions o;
    o.alpha = alpha;
    LatticeReport report;
    const std::vector<Field> k = lattice_coefficients(g, spectra, o, "test", &report);
    double worst = 0.0, scale = 0.0;
    for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
        const double x = i * g.dx(), y = j * g.dy();
        const double r0 = cell_integral(cos2, x, y, g.dx(), g.dy());
        const double r1 = cell_integral(cos1, x, y, g.dx(), g.dy());
        worst = std::max({worst, std::abs(k[0](i, j) - r0), std::abs(k[1](i, j) - r1)});
        scale = std::max({scale, std::abs(r0), std::abs(r1)});
      }
    INFO("alpha = " << alpha << ", evaluations " << report.evaluations);
    CHECK(worst < 1e-12 * scale);
    CHECK_FALSE(report.alias_capped);
  }
  LatticeOptions tight;
  tight.max_evaluations = 10;
  CHECK_THROWS_AS(lattice_coefficients(g, spectra, tight, "test"), InvalidArgument);
}

TEST_CASE("a coating of the substrate's material gives the half-space's closed forms",
          "[traction_kernels]") {
  const Grid g(41, 33, 4e-3, 3e-3);
  const TractionKernels hs = traction_kernels(g, LayerStack{substrate});
  TractionKernelReport report;
  const TractionKernels same = traction_kernels(
      g, LayerStack({Coating{substrate, 2e-4, Interface::bonded}}, substrate), {}, &report);
  CHECK(report.beta == 2e-4);
  CHECK(report.lattice.evaluations > 0);
  const auto difference = [](const Field& a, const Field& b) {
    return (a - b).abs().maxCoeff() / a.abs().maxCoeff();
  };
  // The split (frf-split for H_zz and S, the angular closed forms and the lattice) reproduces
  // Love's and Cerruti's coefficients to rounding: measured 5e-15.
  CHECK(difference(hs.zp, same.zp) < 1e-13);
  CHECK(difference(hs.xx, same.xx) < 1e-13);
  CHECK(difference(hs.yy, same.yy) < 1e-13);
  CHECK(difference(hs.yx, same.yx) < 1e-13);
  CHECK(difference(hs.zx, same.zx) < 1e-13);
  CHECK(difference(hs.zy, same.zy) < 1e-13);
}

TEST_CASE("layered kernels on a square grid are symmetric under the swap of x and y",
          "[traction_kernels]") {
  // u_y under q_y is u_x under q_x turned by 90 degrees, likewise u_z under q_y, and u_y under
  // q_x = u_x under q_y is symmetric: the y kernels are built by other formulas (the swapped
  // closed forms, S - D cos 2theta, sin theta R_C on the lattice), so this checks them.
  const Grid g(33, 33, 3e-3, 3e-3);
  const TractionKernels k = traction_kernels(g, coated(10.0, 2e-4));
  const double scale = k.xx.abs().maxCoeff();
  CHECK((k.yy - k.xx.transpose()).abs().maxCoeff() < 1e-13 * scale);
  CHECK((k.zy - k.zx.transpose()).abs().maxCoeff() < 1e-13 * scale);
  CHECK((k.yx - k.yx.transpose()).abs().maxCoeff() < 1e-13 * scale);
  // Parities: odd kernels vanish on their axis of oddness (cell centres on it), to the rounding
  // of the far-field quadrature's sums over symmetric nodes.
  CHECK(k.zx.row(0).abs().maxCoeff() < 1e-15 * scale);
  CHECK(k.yx.row(0).abs().maxCoeff() < 1e-15 * scale);
  CHECK(k.yx.col(0).abs().maxCoeff() < 1e-15 * scale);
}

TEST_CASE("coated bodies under a Hertz traction and pressure converge to the Hankel reference",
          "[traction_kernels]") {
  // Grids of cell a/m over [-2a, 2a]^2 + a cell (N = 4m + 1, the origin a cell centre), the
  // cell-averaged Hertz-type load q0 sqrt(1 - r^2/a^2) as q_x and as p. Largest error of the
  // three displacements at eight points on and off the axes, over |u_x(0)| (traction) and
  // u_z(0) (pressure): measured 1.7e-3 and 4.4e-4 (E1/E2 = 10, h = a), 4.4e-3 and 1.2e-3
  // (E1/E2 = 0.1, h = a/10) at a/8 and a/16 (4.4e-4 and 2.1e-4, 1.2e-3 and 3.2e-4 at a/16 and
  // a/32) -- the piecewise-constant load's error, which the half-space's closed-form kernels show
  // as well (1.4e-3 and 5.6e-4 over a whole grid of points at a/16 and a/32). The bounds are
  // about twice the a/8 values, and the error must fall with the grid.
  const double a = 1e-3;
  const double points[][2] = {{0.0, 0.0},         {0.5e-3, 0.0},      {1.25e-3, 0.0},
                              {0.0, 0.75e-3},     {0.5e-3, 0.5e-3},   {-1e-3, 0.75e-3},
                              {0.25e-3, -1.5e-3}, {1.75e-3, 1.125e-3}};
  struct Case {
    double e_ratio, h, tol8;
  };
  for (const Case c : {Case{10.0, 1.0 * a, 3.5e-3}, Case{0.1, 0.1 * a, 9e-3}}) {
    const LayerStack body = coated(c.e_ratio, c.h);
    std::vector<SurfaceDisplacement> ref_q, ref_p;
    for (const auto& p : points) {
      ref_q.push_back(axisymmetric_surface_displacement(
          body, AxisymmetricLoad::hertz, LoadDirection::traction_x, 1.0, a, p[0], p[1], 1e-9));
      ref_p.push_back(axisymmetric_surface_displacement(
          body, AxisymmetricLoad::hertz, LoadDirection::pressure, 1.0, a, p[0], p[1], 1e-9));
    }
    std::vector<double> errors;
    for (int m : {8, 16}) {
      const int n = 4 * m + 1;
      const Grid g(n, n, n * a / m, n * a / m);
      const Field load = hertz_pressure(g, 1.0, a, Sampling::cell_average);
      const Field zero = Field::Zero(n, n);
      CerrutiOperator op(g, body, TractionKernelOptions{});
      std::array<Field, 3> uq, up;
      op.apply(zero, &load, nullptr, uq);
      op.apply(load, nullptr, nullptr, up);
      double e = 0.0;
      for (std::size_t k = 0; k < std::size(points); ++k) {
        const auto i = static_cast<std::ptrdiff_t>(std::lround(points[k][0] / g.dx())) + 2 * m;
        const auto j = static_cast<std::ptrdiff_t>(std::lround(points[k][1] / g.dy())) + 2 * m;
        REQUIRE(std::abs(g.x(i) - points[k][0]) < 1e-12);
        REQUIRE(std::abs(g.y(j) - points[k][1]) < 1e-12);
        const double sq = std::abs(ref_q[0].ux), sp = ref_p[0].uz;
        e = std::max(
            {e, std::abs(uq[0](i, j) - ref_q[k].ux) / sq, std::abs(uq[1](i, j) - ref_q[k].uy) / sq,
             std::abs(uq[2](i, j) - ref_q[k].uz) / sq, std::abs(up[0](i, j) - ref_p[k].ux) / sp,
             std::abs(up[1](i, j) - ref_p[k].uy) / sp, std::abs(up[2](i, j) - ref_p[k].uz) / sp});
      }
      errors.push_back(e);
    }
    INFO("E1/E2 = " << c.e_ratio << ", h = " << c.h << ": " << errors[0] << ", " << errors[1]);
    CHECK(errors[0] < c.tol8);
    CHECK(errors[1] < errors[0] / 2.0);  // the load's discretisation error, not a floor
  }
}

TEST_CASE("traction kernels refuse frictionless interfaces and too thin coatings",
          "[traction_kernels]") {
  const Grid g(33, 33, 4e-3, 4e-3);
  CHECK_THROWS_AS(
      traction_kernels(g,
                       LayerStack({Coating{substrate, 1e-4, Interface::frictionless}}, substrate)),
      InvalidArgument);
  // h = L/4000: about 111 (L/h)^2 = 1.8e9 evaluations, refused before any work.
  const LayerStack thin = coated(100.0, 1e-6);
  CHECK(traction_kernel_evaluations(g, thin) > 1e9);
  CHECK_THROWS_AS(traction_kernels(g, thin), InvalidArgument);
  CHECK(traction_kernel_evaluations(g, LayerStack{substrate}) == 0.0);
}

TEST_CASE("the Hankel reference of the half-space equals Johnson's closed forms",
          "[traction_kernels]") {
  // Johnson (1985): the Hertz-type traction q0 sqrt(1 - r^2/a^2) along x gives, for r <= a,
  // u_x = pi q0/(32 G a) [4 (2 - nu) a^2 - (4 - 3 nu) x^2 - (4 - nu) y^2], u_y = pi q0/(32 G a)
  // 2 nu x y (section 3.6); the Hertz pressure the radial displacement
  // u_r = -(1 - 2 nu)(1 + nu)/(3 E) (a^2/r) p0 [1 - (1 - r^2/a^2)^(3/2)] (eq. 3.41a) and u_z of
  // validation/hertz.hpp. The reference is a different route (Hankel integrals of LayerModes).
  const double a = 1e-3, q0 = 1e8, G = substrate.shear_modulus(), nu = 0.3;
  const double E = substrate.youngs_modulus();
  const LayerStack half{substrate};
  const double scale = pi * q0 / (32 * G * a) * 4 * (2 - nu) * a * a;  // u_x(0)
  for (const auto& p :
       {std::array<double, 2>{0.0, 0.0}, {0.5e-3, 0.0}, {0.3e-3, 0.4e-3}, {-0.6e-3, 0.7e-3}}) {
    const double x = p[0], y = p[1], r = std::hypot(x, y);
    const SurfaceDisplacement q = axisymmetric_surface_displacement(
        half, AxisymmetricLoad::hertz, LoadDirection::traction_x, q0, a, x, y, 1e-10);
    const double ux =
        pi * q0 / (32 * G * a) * (4 * (2 - nu) * a * a - (4 - 3 * nu) * x * x - (4 - nu) * y * y);
    CHECK(std::abs(q.ux - ux) < 1e-9 * scale);
    CHECK(std::abs(q.uy - pi * q0 / (32 * G * a) * 2 * nu * x * y) < 1e-9 * scale);
    const SurfaceDisplacement v = axisymmetric_surface_displacement(
        half, AxisymmetricLoad::hertz, LoadDirection::pressure, q0, a, x, y, 1e-10);
    const double ur = r > 0 ? -(1 - 2 * nu) * (1 + nu) / (3 * E) * a * a / r * q0 *
                                  (1 - std::pow(1 - r * r / (a * a), 1.5))
                            : 0.0;
    CHECK(std::abs(v.ux - (r > 0 ? ur * x / r : 0.0)) < 1e-9 * scale);
    CHECK(std::abs(v.uy - (r > 0 ? ur * y / r : 0.0)) < 1e-9 * scale);
    CHECK(v.uz ==
          Approx(hertz_displacement(r, q0, a, substrate.plane_strain_modulus())).epsilon(1e-9));
    // Betti: u_z under the traction is minus u_x under the pressure at the same point.
    CHECK(std::abs(q.uz + v.ux) < 1e-9 * scale);
  }
}
