#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>

#include "convolution/kernels/frf_influence_kernel.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/frf_spectral_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/norms.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"
#include "test_g0_frfs.hpp"
#include "validation/hertz.hpp"

using namespace coatfft;
using coatfft::testing::CoatingFrf;
using coatfft::testing::InverseKFrf;
using std::numbers::pi;

namespace {

const Material steel(210e9, 0.3);
constexpr double a = 1e-3, p0 = 1e9;

struct HertzCase {
  Grid grid;
  Field pressure;
  Field exact;
  double u0;
};

HertzCase hertz_case(std::ptrdiff_t n) {
  const Grid g(n, n, 3 * a, 3 * a);
  const double E = steel.plane_strain_modulus();
  return {g, hertz_pressure(g, p0, a, Sampling::centre), hertz_displacement_field(g, p0, a, E),
          hertz_displacement(0, p0, a, E)};
}

// Wrap-around signed index of slot j on an m-point lattice.
double signed_index(std::ptrdiff_t j, std::ptrdiff_t m) {
  return static_cast<double>(j < (m + 1) / 2 ? j : j - m);
}

// The periodised kernel G(di, dj) = (1/(mx my)) sum_k S(k) H(k) exp(+i k.d) by a direct double
// sum over the whole lattice (no FFT, no half spectrum, no layout tricks); `cell` multiplies by
// the cell transform sinc(kx dx/2) sinc(ky dy/2) of docs/theory.md (4.1).
double direct_periodic_kernel(const Frf& frf, double g0, const Grid& g, std::ptrdiff_t mx,
                              std::ptrdiff_t my, std::ptrdiff_t di, std::ptrdiff_t dj, bool cell) {
  const double dkx = 2 * pi / (mx * g.dx()), dky = 2 * pi / (my * g.dy());
  std::complex<double> sum = 0;
  for (std::ptrdiff_t jy = 0; jy < my; ++jy)
    for (std::ptrdiff_t jx = 0; jx < mx; ++jx) {
      const double kx = dkx * signed_index(jx, mx), ky = dky * signed_index(jy, my);
      double h = (jx == 0 && jy == 0) ? g0 : frf(std::hypot(kx, ky));
      if (cell) {
        const double sx = kx == 0 ? 1 : std::sin(kx * g.dx() / 2) / (kx * g.dx() / 2);
        const double sy = ky == 0 ? 1 : std::sin(ky * g.dy() / 2) / (ky * g.dy() / 2);
        h *= sx * sy;
      }
      const double phase = 2 * pi * (double(jx * di) / mx + double(jy * dj) / my);
      sum += h * std::polar(1.0, phase);
    }
  return sum.real() / (double(mx) * double(my));
}

Field random_pressure(std::ptrdiff_t nx, std::ptrdiff_t ny) {
  Field p(nx, ny);
  unsigned s = 12345u;  // fixed-seed LCG: reproducible, no <random> distribution differences
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      s = 1664525u * s + 1013904223u;
      p(i, j) = 1e6 * (0.25 + double(s >> 8) / double(1u << 24));
    }
  return p;
}

}  // namespace

TEST_CASE("FRF-spectral equals a direct periodic convolution on small odd grids",
          "[frf_pipelines]") {
  // Independent reference: u_i = sum_k p_k G((i - k) mod M) with G from a direct DFT double sum.
  // Catches layout, wrap-around, Nyquist and normalisation mistakes; agreement to round-off
  // (1e-12 relative to max |u|, the sums have ~1e3 terms of one sign).
  const CoatingFrf frf(400e9, .25, 210e9, .3, 2e-4, true);
  const auto [nx, ny, alpha] = GENERATE(table<std::ptrdiff_t, std::ptrdiff_t, double>(
      {{5, 4, 3.0}, {3, 7, 2.0}, {6, 6, 1.0}, {1, 5, 2.0}, {4, 4, 1.5}}));
  const Grid g(nx, ny, 1e-3, 1.3e-3);
  FrfSpectralOperator op(g, frf, alpha, G0Method::regularized);
  const std::ptrdiff_t mx = op.extended_nx(), my = op.extended_ny();
  REQUIRE(mx == std::lround(alpha * nx));
  const Field p = random_pressure(nx, ny);
  const Field u = op.apply(p);
  Field ref = Field::Zero(nx, ny);
  for (std::ptrdiff_t dj = -(ny - 1); dj <= ny - 1; ++dj)
    for (std::ptrdiff_t di = -(nx - 1); di <= nx - 1; ++di) {
      const double G = direct_periodic_kernel(frf, op.g0().value, g, mx, my, di, dj, false);
      for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, dj);
           j < ny + std::min<std::ptrdiff_t>(0, dj); ++j)
        for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(0, di);
             i < nx + std::min<std::ptrdiff_t>(0, di); ++i)
          ref(i, j) += G * p(i - di, j - dj);
    }
  CAPTURE(nx, ny, alpha);
  CHECK(rel_linf(u, ref) < 1e-12);
}

TEST_CASE("FRF influence coefficients equal the direct sum of docs/theory.md (4.1)",
          "[frf_pipelines]") {
  // Same independent double sum, with the cell factor: checks the sinc, the half-spectrum c2r and
  // the copy of offsets |d| <= n - 1 into the (2nx, 2ny) wrap-around layout. Round-off: 1e-12
  // of K(0, 0).
  const CoatingFrf frf(70e9, .3, 210e9, .3, 1e-4, false);
  const auto [nx, ny, alpha] = GENERATE(
      table<std::ptrdiff_t, std::ptrdiff_t, double>({{4, 3, 2.0}, {3, 5, 3.0}, {5, 5, 2.4}}));
  const Grid g(nx, ny, 1e-3, 0.8e-3);
  G0Result g0{};
  const InfluenceKernel K = frf_influence_kernel(g, frf, alpha, G0Method::regularized, 1e-13, &g0);
  const std::ptrdiff_t mx = std::lround(alpha * nx), my = std::lround(alpha * ny);
  const double k00 = direct_periodic_kernel(frf, g0.value, g, mx, my, 0, 0, true);
  for (std::ptrdiff_t dj = -(ny - 1); dj <= ny - 1; ++dj)
    for (std::ptrdiff_t di = -(nx - 1); di <= nx - 1; ++di) {
      CAPTURE(nx, ny, alpha, di, dj);
      CHECK(std::abs(K.at(di, dj) -
                     direct_periodic_kernel(frf, g0.value, g, mx, my, di, dj, true)) < 1e-12 * k00);
    }
}

TEST_CASE("A g(0) perturbation shifts the whole field uniformly (Spinu 2021, Figure 3(b))",
          "[frf_pipelines]") {
  // u = IFFT_M(H . FFT_M(p)): changing H(0) by dg adds dg * FFT_M(p)(0) / (mx my)
  // = dg * sum(p) / (mx my) to every slot, i.e. dg * P / (mx dx my dy), the load over the area
  // of the period. For FRF -> DC-FFT every coefficient K(d), |d| <= N - 1, moves by dg/(mx my)
  // (sinc(0) = 1), and every pair of target cells is within that range: the same shift. Checked
  // to 1e-12 of the shift (the shift is ~10% of u, FFT round-off ~1e-15 of u).
  const Grid g(24, 20, 3e-3, 2.5e-3);
  const Field p = random_pressure(24, 20);
  const CoatingFrf frf(400e9, .25, 210e9, .3, 2e-4, true);
  for (const double alpha : {2.0, 2.5}) {
    FrfSpectralOperator base(g, frf, alpha, G0Method::regularized);
    const double mxmy = double(base.extended_nx()) * double(base.extended_ny());
    G0Result shifted = base.g0();
    const double dg = 0.3 * shifted.value;
    shifted.value += dg;
    const double expected = dg * p.sum() / mxmy;
    FrfSpectralOperator perturbed(g, frf, alpha, shifted);
    const Field d1 = perturbed.apply(p) - base.apply(p);
    CHECK((d1 - expected).abs().maxCoeff() < 1e-12 * expected);
    DcfftOperator kb(frf_influence_kernel(g, frf, alpha, base.g0()));
    DcfftOperator kp(frf_influence_kernel(g, frf, alpha, shifted));
    const Field d2 = kp.apply(p) - kb.apply(p);
    CHECK((d2 - expected).abs().maxCoeff() < 1e-12 * expected);
  }
}

TEST_CASE("A coating of the substrate's own material gives the homogeneous result",
          "[frf_pipelines]") {
  // Bonded, identical media: C(t) = 1 exactly (alpha = beta = 0), so H, g(0) and both pipelines
  // must equal the half-space ones to round-off (1e-12 relative).
  const HertzCase h = hertz_case(32);
  const InverseKFrf homogeneous(steel.plane_strain_modulus());
  const CoatingFrf coated(210e9, 0.3, 210e9, 0.3, 0.2e-3, true);
  for (const double alpha : {2.0, 3.0}) {
    FrfSpectralOperator s0(h.grid, homogeneous, alpha, G0Method::regularized);
    FrfSpectralOperator s1(h.grid, coated, alpha, G0Method::regularized);
    CHECK(s1.g0().value == Approx(s0.g0().value).epsilon(1e-14));
    CHECK(rel_linf(s1.apply(h.pressure), s0.apply(h.pressure)) < 1e-12);
    DcfftOperator k0(frf_influence_kernel(h.grid, homogeneous, alpha, G0Method::regularized));
    DcfftOperator k1(frf_influence_kernel(h.grid, coated, alpha, G0Method::regularized));
    CHECK(rel_linf(k1.apply(h.pressure), k0.apply(h.pressure)) < 1e-12);
  }
}

TEST_CASE("FRF pipelines refuse bad extension ratios and shapes", "[frf_pipelines][bad_input]") {
  const Grid g(10, 8, 1e-3, 1e-3);
  const InverseKFrf frf(1e11);
  CHECK_THROWS_WITH(FrfSpectralOperator(g, frf, 0.5, G0Method::regularized),
                    Catch::Contains("alpha = 0.5"));
  CHECK_THROWS_WITH(FrfSpectralOperator(g, frf, 2.05, G0Method::regularized),
                    Catch::Contains("not an integer"));
  CHECK_THROWS_AS(FrfSpectralOperator(g, frf, NAN, G0Method::regularized), InvalidArgument);
  CHECK_THROWS_WITH(frf_influence_kernel(g, frf, 1.5, G0Method::regularized),
                    Catch::Contains(">= 2"));
  G0Result bad{NAN, G0Method::regularized, 0, 0};
  CHECK_THROWS_AS(FrfSpectralOperator(g, frf, 2.0, bad), InvalidArgument);
  CHECK_THROWS_AS(frf_influence_kernel(g, frf, 2.0, bad), InvalidArgument);
  FrfSpectralOperator op(g, frf, 2.0, G0Method::regularized);
  CHECK(op.name() == "frf-spectral");
  CHECK_THROWS_WITH(op.apply(Field::Zero(8, 10)), Catch::Contains("shape (8, 10)"));
}

TEST_CASE("FRF sampling and coefficients on square lattices and several threads",
          "[frf_pipelines]") {
  // sample_frf_half_spectrum evaluates H once per |ky| and, on a square lattice (dkx == dky),
  // once per unordered pair (jx, |jy|), on several threads; every entry must still be
  // H(hypot(kx, ky)) at its own wavenumber (wrap-around signs included). Each value is the FRF at
  // the same argument up to the order of hypot's operands: 1e-15 relative.
  const CoatingFrf frf(70e9, .3, 210e9, .3, 1e-4, false);
  struct Lattice {
    std::ptrdiff_t mx, my;
    double dx, dy;
  };
  for (const Lattice l :
       {Lattice{8, 8, 1e-4, 1e-4}, Lattice{9, 7, 1e-4, 1e-4}, Lattice{10, 6, 1e-4, 0.7e-4},
        Lattice{7, 11, 1e-4, 1e-4}, Lattice{4, 8, 2e-4, 1e-4}, Lattice{8, 4, 1e-4, 2e-4}}) {
    // The last two have equal spacings (mx dx == my dy) on a non-square quarter.
    for (int threads : {1, 3}) {
      const Field h = sample_frf_half_spectrum(frf, l.mx, l.my, l.dx, l.dy, 1.25e-11, threads);
      REQUIRE(h.rows() == l.mx / 2 + 1);
      REQUIRE(h.cols() == l.my);
      const double dkx = 2 * pi / (l.mx * l.dx), dky = 2 * pi / (l.my * l.dy);
      for (std::ptrdiff_t jy = 0; jy < l.my; ++jy)
        for (std::ptrdiff_t jx = 0; jx <= l.mx / 2; ++jx) {
          CAPTURE(l.mx, l.my, threads, jx, jy);
          const double expected =
              jx == 0 && jy == 0
                  ? 1.25e-11
                  : frf(std::hypot(dkx * double(jx), dky * double(signed_index(jy, l.my))));
          CHECK(h(jx, jy) == Approx(expected).epsilon(1e-15).margin(0.0));
        }
    }
  }
  // frf_influence_kernel on a square lattice (DCT-I route with the swap symmetry) and with 2
  // threads, against the independent double sum of docs/theory.md (4.1): 1e-12 of K(0, 0) as above.
  const Grid g(4, 4, 1e-3, 1e-3);
  const G0Result g0 =
      compute_g0(frf, 2 * pi / (8 * g.dx()), 2 * pi / (8 * g.dy()), G0Method::regularized);
  const InfluenceKernel K = frf_influence_kernel(g, frf, 2.0, g0, 2);
  const double k00 = direct_periodic_kernel(frf, g0.value, g, 8, 8, 0, 0, true);
  for (std::ptrdiff_t dj = -3; dj <= 3; ++dj)
    for (std::ptrdiff_t di = -3; di <= 3; ++di) {
      CAPTURE(di, dj);
      CHECK(std::abs(K.at(di, dj) - direct_periodic_kernel(frf, g0.value, g, 8, 8, di, dj, true)) <
            1e-12 * k00);
    }
  CHECK_THROWS_AS(frf_influence_kernel(g, frf, 2.0, g0, 0), InvalidArgument);
}

TEST_CASE("frf-dcfft at alpha = 2 (spectrum form) equals the coefficient route",
          "[frf_pipelines]") {
  // The spectrum route skips the DCT round trip of the coefficients; the reference is the plain
  // route: coefficients by frf_influence_kernel, then DcfftOperator's own transform. Both compute
  // the same convolution; they differ only in rounding (two 2-D DCTs, ~1e-15) and in the
  // offsets +-nx, +-ny, which must not reach the output.
  const CoatingFrf coated(600e9, 0.25, 210e9, 0.3, 0.05e-3, true);
  struct Shape {
    std::ptrdiff_t nx, ny;
    double lx, ly;
  };
  for (const Shape sh :
       {Shape{1, 1, 1e-3, 1e-3}, Shape{1, 7, 1e-3, 2e-3}, Shape{7, 1, 3e-3, 1e-3},
        Shape{31, 33, 2e-3, 2e-3}, Shape{64, 64, 2e-3, 2e-3}, Shape{40, 24, 2e-3, 3e-3}}) {
    INFO(sh.nx << " x " << sh.ny);
    const Grid g(sh.nx, sh.ny, sh.lx, sh.ly);
    const Field p = random_pressure(sh.nx, sh.ny);
    OperatorOptions options;
    options.method = Method::frf_dcfft;
    options.g0_tolerance = 1e-13;
    const BuiltOperator fast = make_operator(g, coated, options);
    REQUIRE(fast.report.g0);
    const G0Result g0 = *fast.report.g0;
    DcfftOperator plain(frf_influence_kernel(g, coated, 2.0, g0));
    CHECK(frf_dcfft_kernel(g, coated, 2.0, g0).form() == InfluenceKernel::Form::spectrum);
    CHECK(fast.op->method() == Method::frf_dcfft);
    CHECK(std::isfinite(g0.value));
    CHECK(rel_linf(fast.op->apply(p), plain.apply(p)) < 1e-13);
    // Other ratios take the coefficient route itself: identical.
    DcfftOperator at3(frf_dcfft_kernel(g, coated, 3.0, g0));
    DcfftOperator plain3(frf_influence_kernel(g, coated, 3.0, g0));
    CHECK(rel_linf(at3.apply(p), plain3.apply(p)) == 0.0);
  }
}

TEST_CASE("frf-dcfft's kernel, its options and the spectrum form refuse bad input",
          "[frf_pipelines][bad_input]") {
  const Grid g(10, 8, 1e-3, 1e-3);
  const InverseKFrf frf(1e11);
  const G0Result ok{1e-12, G0Method::regularized, 0, 0};
  CHECK_THROWS_WITH(frf_dcfft_kernel(g, frf, 1.5, ok), Catch::Contains(">= 2"));
  CHECK_THROWS_WITH(frf_dcfft_kernel(g, frf, 2.05, ok), Catch::Contains("not an integer"));
  OperatorOptions options;
  options.method = Method::frf_dcfft;
  options.alpha = 1.5;
  CHECK_THROWS_WITH(make_operator(g, frf, options), Catch::Contains(">= 2"));
  options.alpha = 2.05;
  CHECK_THROWS_WITH(make_operator(g, frf, options), Catch::Contains("whole numbers"));
  const G0Result bad{NAN, G0Method::regularized, 0, 0};
  CHECK_THROWS_WITH(frf_dcfft_kernel(g, frf, 2.0, bad), Catch::Contains("g(0) = nan"));
  CHECK_THROWS_AS(frf_dcfft_kernel(g, frf, 4.0, bad), InvalidArgument);
  CHECK_THROWS_WITH(InfluenceKernel(g, InfluenceKernel::Form::spectrum, Field::Ones(10, 8)),
                    Catch::Contains("shape (10, 8)"));
  Field nan_spectrum = Field::Ones(11, 9);
  nan_spectrum(3, 4) = NAN;
  CHECK_THROWS_WITH(InfluenceKernel(g, InfluenceKernel::Form::spectrum, nan_spectrum),
                    Catch::Contains("not finite"));
}
