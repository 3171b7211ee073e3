// frf-split influence coefficients (convolution/kernels/split_frf_kernel.hpp): the closed-form cell
// integral, the homogeneous limits (exactly Love), the remainder machinery against closed forms,
// and coated Hertz displacements against the continuous Hankel reference.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "convolution/kernels/detail/cell_average_stencil.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "frf/coated_frf.hpp"
#include "frf/half_space_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "validation/hankel_displacement.hpp"

namespace {

using namespace coatfft;

// H(k) = c_inf/k + A exp(-b k)/k: the split is exact with (a) + (b) alone when beta = b, so its
// coefficients have the closed form (c_inf/2) love + (A/2 pi) split_rectangle_integral.
class ExponentialFrf final : public Frf {
 public:
  ExponentialFrf(double c0, double c_inf, double b) : c0_(c0), c_inf_(c_inf), b_(b) {}
  double operator()(double k) const override {
    return (c_inf_ + (c0_ - c_inf_) * std::exp(-b_ * k)) / k;
  }
  double c0() const override { return c0_; }
  double c_inf() const override { return c_inf_; }
  std::string name() const override { return "exponential"; }

 private:
  double c0_;
  double c_inf_;
  double b_;
};

double closed_form(const ExponentialFrf& frf, double b, double x, double y, double dx, double dy) {
  return 0.5 * frf.c_inf() * love_influence(x, y, dx, dy) +
         (frf.c0() - frf.c_inf()) / (2.0 * M_PI) *
             detail::split_rectangle_integral(x, y, dx, dy, b);
}

// Composite Gauss-Legendre (4 x 4 panels of 20 nodes) of 1/sqrt(r^2 + b^2) over the cell: the
// integrand is analytic within b of the cell, so this converges to rounding for b >= 0.1 d.
double quadrature_rectangle(double x, double y, double dx, double dy, double b) {
  static const std::vector<double> t = {
      -0.9931285991850949, -0.9639719272779138, -0.9122344282513259, -0.8391169718222188,
      -0.7463319064601508, -0.6360536807265150, -0.5108670019508271, -0.3737060887154195,
      -0.2277858511416451, -0.0765265211334973, 0.0765265211334973,  0.2277858511416451,
      0.3737060887154195,  0.5108670019508271,  0.6360536807265150,  0.7463319064601508,
      0.8391169718222188,  0.9122344282513259,  0.9639719272779138,  0.9931285991850949};
  static const std::vector<double> w = {
      0.0176140071391521, 0.0406014298003869, 0.0626720483341091, 0.0832767415767048,
      0.1019301198172404, 0.1181945319615184, 0.1316886384491766, 0.1420961093183820,
      0.1491729864726037, 0.1527533871307258, 0.1527533871307258, 0.1491729864726037,
      0.1420961093183820, 0.1316886384491766, 0.1181945319615184, 0.1019301198172404,
      0.0832767415767048, 0.0626720483341091, 0.0406014298003869, 0.0176140071391521};
  constexpr int panels = 4;
  double sum = 0.0;
  for (int pi = 0; pi < panels; ++pi)
    for (int pj = 0; pj < panels; ++pj)
      for (std::size_t i = 0; i < t.size(); ++i)
        for (std::size_t j = 0; j < t.size(); ++j) {
          const double xs = dx * (-0.5 + (pi + 0.5 + 0.5 * t[i]) / panels);
          const double ys = dy * (-0.5 + (pj + 0.5 + 0.5 * t[j]) / panels);
          const double rx = x - xs;
          const double ry = y - ys;
          sum += w[i] * w[j] / std::sqrt(rx * rx + ry * ry + b * b);
        }
  return sum * dx * dy / (4.0 * panels * panels);
}

double max_abs_difference(const InfluenceKernel& a, const InfluenceKernel& b) {
  return (a.wrapped() - b.wrapped()).abs().maxCoeff();
}

// Centre, 0.5a, a and 2a cells of a DC-FFT Hertz displacement (odd n, the origin a cell centre).
std::vector<double> hertz_profile(const InfluenceKernel& kernel, double a, double cell) {
  const Grid& grid = kernel.grid();
  DcfftOperator op(kernel);
  const Field u = op.apply(hertz_pressure(grid, 1.0, a, Sampling::cell_average));
  const std::ptrdiff_t c = grid.nx() / 2;
  std::vector<double> out;
  for (double r : {0.0, 0.5, 1.0, 2.0}) out.push_back(u(c + std::lround(r * a / cell), c));
  return out;
}

}  // namespace

TEST_CASE("split_rectangle_integral is the cell integral of 1/sqrt(r^2 + beta^2)", "[split]") {
  // Independent reference: composite Gauss-Legendre, converged to ~1e-15 (see its comment); the
  // 4-corner closed form loses ~log10(r/d) digits to cancellation, so 1e-13 relative.
  struct Point {
    double x, y, dx, dy, b;
  };
  const std::vector<Point> points = {{0.0, 0.0, 1.0, 1.0, 0.3},   {0.0, 0.0, 1.0, 0.4, 2.0},
                                     {1.0, 0.0, 1.0, 1.0, 0.1},   {3.0, -2.0, 1.0, 0.5, 0.7},
                                     {-0.5, 0.5, 1.0, 1.0, 0.25}, {12.0, 7.0, 1.0, 1.0, 30.0}};
  for (const Point& p : points) {
    const double ref = quadrature_rectangle(p.x, p.y, p.dx, p.dy, p.b);
    CHECK(detail::split_rectangle_integral(p.x, p.y, p.dx, p.dy, p.b) ==
          Approx(ref).epsilon(1e-13));
  }
  // beta -> 0: Love's rectangle, u = (1/pi) \iint 1/r (docs/theory.md (1.5)); the difference
  // is O(beta).
  for (const Point& p : points) {
    const double love = M_PI * love_influence(p.x, p.y, p.dx, p.dy);
    CHECK(detail::split_rectangle_integral(p.x, p.y, p.dx, p.dy, 1e-10) ==
          Approx(love).epsilon(1e-8));
  }
}

TEST_CASE("split kernel of a homogeneous body is Love's kernel", "[split]") {
  const Grid grid(33, 21, 2.0, 1.4);
  const double E_star = Material(2.1e11, 0.3).plane_strain_modulus();
  const InfluenceKernel love = love_kernel(grid, E_star);
  const double k00 = love.at(0, 0);
  SECTION("half-space FRF") {
    SplitKernelReport report;
    const InfluenceKernel split =
        split_frf_kernel(grid, HalfSpaceFrf(Material(2.1e11, 0.3)), {}, &report);
    CHECK(report.remainder_zero);
    // Only 2 / (2 / E*) differs from E* in the last bit.
    CHECK(max_abs_difference(split, love) <= 1e-14 * k00);
  }
  SECTION("bonded coating identical to the substrate") {
    // (A frictionless interface inside one material is not homogeneous: it slips.)
    const CoatedFrf frf(Material(2.1e11, 0.3), 0.05, Material(2.1e11, 0.3), Interface::bonded);
    SplitKernelReport report;
    const InfluenceKernel split = split_frf_kernel(grid, frf, {}, &report);
    CHECK(report.remainder_zero);
    CHECK(max_abs_difference(split, love) <= 1e-14 * k00);
  }
  SECTION("Hertz centre displacement through DC-FFT agrees to 1e-12 of u(0)") {
    const Grid g(65, 65, 65.0 / 16.0, 65.0 / 16.0);
    const CoatedFrf frf(Material(2.1e11, 0.3), 0.3, Material(2.1e11, 0.3), Interface::bonded);
    const auto u_split = hertz_profile(split_frf_kernel(g, frf), 1.0, 1.0 / 16.0);
    const auto u_love = hertz_profile(love_kernel(g, E_star), 1.0, 1.0 / 16.0);
    for (std::size_t i = 0; i < u_love.size(); ++i)
      CHECK(std::abs(u_split[i] - u_love[i]) <= 1e-12 * u_love[0]);
  }
}

TEST_CASE("split remainder reproduces the closed form of an exponential FRF", "[split]") {
  // With beta = b (also what the automatic first-moment choice finds) the remainder is zero and
  // the kernel is the closed form; with beta = 2.5 b the remainder A (exp(-b k) - exp(-2.5 b k))/k
  // is not, and the same kernel must come out of the Hankel table and the alias fold. Tolerance
  // 1e-9 of K(0, 0): the default tolerance is 1e-11 per truncation, and the 4-corner sums lose ~2
  // digits to cancellation at the far cells.
  const double c0 = 3.0;
  const double c_inf = 1.0;
  struct Setup {
    const char* what;
    Grid grid;
    double b;
  };
  const std::vector<Setup> setups = {
      {"b ~ cell", Grid(24, 24, 3.0, 3.0), 0.2},
      // R's spectrum reaches 25/b = 8 Nyquists: only the alias fold gets this right.
      {"b < cell/10", Grid(17, 17, 1.7, 1.7), 0.01},
      // R's kernel reaches far beyond the domain: the Hankel part must carry it.
      {"b >> domain", Grid(20, 16, 2.0, 1.6), 10.0},
      {"rectangular cells", Grid(16, 12, 2.0, 0.9), 0.1},
  };
  for (const Setup& s : setups) {
    INFO(s.what);
    const ExponentialFrf frf(c0, c_inf, s.b);
    SplitKernelReport report;
    const InfluenceKernel exact_kernel = split_frf_kernel(s.grid, frf, {}, &report);
    CHECK(report.beta == Approx(s.b).epsilon(1e-3));
    SplitKernelOptions off;
    off.beta = 2.5 * s.b;
    const InfluenceKernel auto_kernel = split_frf_kernel(s.grid, frf, off);
    const double dx = s.grid.dx();
    const double dy = s.grid.dy();
    const double k00 = closed_form(frf, s.b, 0.0, 0.0, dx, dy);
    double worst_auto = 0.0;
    double worst_exact = 0.0;
    for (std::ptrdiff_t j = 1 - s.grid.ny(); j < s.grid.ny(); ++j)
      for (std::ptrdiff_t i = 1 - s.grid.nx(); i < s.grid.nx(); ++i) {
        const double ref =
            closed_form(frf, s.b, static_cast<double>(i) * dx, static_cast<double>(j) * dy, dx, dy);
        worst_auto = std::max(worst_auto, std::abs(auto_kernel.at(i, j) - ref));
        worst_exact = std::max(worst_exact, std::abs(exact_kernel.at(i, j) - ref));
      }
    CHECK(worst_exact <= 1e-9 * k00);
    CHECK(worst_auto <= 1e-9 * k00);
  }
}

TEST_CASE("cell-average stencil is exact for polynomials of degree 9", "[split]") {
  // sum_j c_|j| j^n = \int_{-1/2}^{1/2} s^n ds (0 for odd n by symmetry), n = 0..9; and not for
  // n = 10 (the error term of cell_average_stencil.hpp).
  const auto& c = detail::cell_average_weights;
  for (int n = 0; n <= 10; n += 2) {
    double sum = c[0] * (n == 0 ? 1.0 : 0.0);
    for (int j = 1; j <= detail::cell_average_half_width; ++j)
      sum += 2.0 * c[static_cast<std::size_t>(j)] * std::pow(j, n);
    const double exact = 1.0 / ((n + 1) * std::pow(2.0, n));
    if (n < 10)
      CHECK(sum == Approx(exact).margin(1e-14 * std::pow(4.0, n)));
    else
      CHECK(std::abs(sum - exact) > 1.0);
  }
}

TEST_CASE("split kernel stencil route reproduces the closed form", "[split]") {
  // Grids fine enough (sigma = L/32 >= 8 cells) for the long part's point values and the
  // 9-point cell-average stencil, which also carries the far cells' (a) + (b): every coefficient
  // against the closed form of an exponential FRF (beta = 2.5 b, so that R is not zero), square
  // cells on a square grid (the symmetric paths) and rectangular cells, 1 and 2 threads.
  struct Setup {
    const char* what;
    Grid grid;
    double b;
  };
  const std::vector<Setup> setups = {{"square", Grid(300, 300, 3.0, 3.0), 0.05},
                                     {"rectangular", Grid(400, 330, 4.0, 3.0), 0.03}};
  for (const Setup& s : setups) {
    INFO(s.what);
    const ExponentialFrf frf(3.0, 1.0, s.b);
    SplitKernelOptions o;
    o.beta = 2.5 * s.b;
    SplitKernelReport report;
    const InfluenceKernel k = split_frf_kernel(s.grid, frf, o, &report);
    CHECK(report.cell_rule == 1);  // the stencil route
    const double dx = s.grid.dx();
    const double dy = s.grid.dy();
    const double k00 = closed_form(frf, s.b, 0.0, 0.0, dx, dy);
    double worst = 0.0;
    for (std::ptrdiff_t j = 0; j < s.grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < s.grid.nx(); ++i) {
        const double ref =
            closed_form(frf, s.b, static_cast<double>(i) * dx, static_cast<double>(j) * dy, dx, dy);
        worst = std::max(worst, std::abs(k.at(i, j) - ref));
      }
    CHECK(worst <= 1e-9 * k00);
    o.threads = 2;
    CHECK(max_abs_difference(k, split_frf_kernel(s.grid, frf, o)) == 0.0);
  }
}

TEST_CASE("split kernel far field: Gauss rules beyond 32, 64 and 512 cells", "[split]") {
  // A 700 x 2 strip reaches offsets of 699 cells, where (a) and (b) switch from the corner
  // formulas to 4 x 4, 3 x 3 and 2 x 2 Gauss-Legendre rules. Reference: the corner formulas
  // themselves, whose cancellation costs ~eps (r/d)^2 = 1e-10 of a coefficient ~K(0,0) r/d
  // smaller, i.e. ~2e-13 of K(0,0): tolerance 1e-12 of K(0,0).
  const double b = 2.0;
  const ExponentialFrf frf(3.0, 1.0, b);
  const Grid grid(700, 2, 7.0, 0.02);
  SplitKernelOptions exact;
  exact.beta = b;
  const InfluenceKernel k = split_frf_kernel(grid, frf, exact);
  const double k00 = closed_form(frf, b, 0.0, 0.0, 0.01, 0.01);
  double worst = 0.0;
  for (std::ptrdiff_t j = 0; j < 2; ++j)
    for (std::ptrdiff_t i = 0; i < 700; ++i) {
      const double ref = closed_form(frf, b, static_cast<double>(i) * 0.01,
                                     static_cast<double>(j) * 0.01, 0.01, 0.01);
      worst = std::max(worst, std::abs(k.at(i, j) - ref));
    }
  CHECK(worst <= 1e-12 * k00);
}

TEST_CASE("split remainder: the fold and the Hankel part are both needed", "[split]") {
  // Sensitivity checks for the test above: truncating R at Nyquist (no aliases) or periodising all
  // of R must both miss the closed form by far more than its tolerance.
  const ExponentialFrf thin(3.0, 1.0, 0.01);
  const Grid g1(17, 17, 1.7, 1.7);
  SplitKernelOptions no_alias;
  no_alias.beta = 0.025;
  no_alias.max_alias_order = 0;
  SplitKernelReport report;
  const InfluenceKernel truncated = split_frf_kernel(g1, thin, no_alias, &report);
  CHECK(report.alias_capped);
  const double k00 = closed_form(thin, 0.01, 0.0, 0.0, g1.dx(), g1.dy());
  CHECK(std::abs(truncated.at(0, 0) - k00) > 1e-3 * k00);

  const ExponentialFrf thick(3.0, 1.0, 10.0);
  const Grid g2(20, 16, 2.0, 1.6);
  SplitKernelOptions periodic;
  periodic.beta = 25.0;
  periodic.route = SplitRoute::periodic;
  const InfluenceKernel p = split_frf_kernel(g2, thick, periodic);
  const double k00b = closed_form(thick, 10.0, 0.0, 0.0, g2.dx(), g2.dy());
  CHECK(std::abs(p.at(0, 0) - k00b) > 1e-2 * k00b);
}

TEST_CASE("split routes agree where each is valid", "[split]") {
  // A coating a few cells thick on a domain 8 thicknesses wide: automatic (windowed) and pure
  // Hankel are independent computations of the same coefficients; 1e-8 of K(0, 0).
  const CoatedFrf frf(Material(10.0, 0.3), 0.25, Material(1.0, 0.25), Interface::bonded);
  const Grid grid(25, 25, 2.0, 2.0);
  SplitKernelOptions hankel;
  hankel.route = SplitRoute::hankel;
  const InfluenceKernel a = split_frf_kernel(grid, frf);
  const InfluenceKernel b = split_frf_kernel(grid, frf, hankel);
  CHECK(max_abs_difference(a, b) <= 1e-8 * a.at(0, 0));
}

TEST_CASE("split kernel: the periodic route alone misses the target", "[split]") {
  // Sensitivity of the test above: periodising R (images of its r^-3 tail) costs ~3% here.
  const double a = 1.0;
  const double cell = a / 16.0;
  const Grid grid(65, 65, 65.0 * cell, 65.0 * cell);
  const CoatedFrf frf(Material(10.0, 0.3), 0.5 * a, Material(1.0, 0.3), Interface::bonded);
  SplitKernelOptions periodic;
  periodic.route = SplitRoute::periodic;
  const auto u = hertz_profile(split_frf_kernel(grid, frf, periodic), a, cell);
  const double u0 = hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, a, 0.0, 1e-8);
  CHECK(std::abs(u[0] - u0) > 1e-2 * u0);
}

TEST_CASE("split kernel: hard cases stay finite", "[split]") {
  // Small grid: the 1e-3 coatings need the capped alias fold, whose cost grows like N^2.
  const Grid grid(17, 17, 17.0 / 8.0, 17.0 / 8.0);
  const std::vector<CoatedFrf> frfs = {
      CoatedFrf(Material(100.0, 0.3), 1e-3, Material(1.0, 0.3), Interface::bonded),
      CoatedFrf(Material(0.01, 0.3), 50.0, Material(1.0, 0.3), Interface::bonded),
      CoatedFrf(Material(1.0, 0.4999), 0.1, Material(100.0, 0.4999), Interface::bonded),
      CoatedFrf(Material(0.01, 0.4999), 1e-3, Material(1.0, 0.2), Interface::frictionless)};
  for (const CoatedFrf& frf : frfs) {
    INFO(frf.name() << " h = " << frf.thickness());
    const InfluenceKernel k = split_frf_kernel(grid, frf);
    CHECK(k.wrapped().allFinite());
    // The self coefficient lies between those of the two half-spaces (2/C0 and 2/Cinf moduli).
    const double lo = 0.5 * std::min(frf.c0(), frf.c_inf()) * love_influence(0, 0, 0.125, 0.125);
    const double hi = 0.5 * std::max(frf.c0(), frf.c_inf()) * love_influence(0, 0, 0.125, 0.125);
    CHECK(k.at(0, 0) >= lo);
    CHECK(k.at(0, 0) <= hi);
  }
}

TEST_CASE("split coefficients depend on the cell, not on the grid", "[split]") {
  // K(di, dj) is a property of (dx, dy) and the body: small and degenerate grids (whose window,
  // lattice and tables all differ) must reproduce a large grid's coefficients; 1e-9 of K(0, 0).
  const CoatedFrf frf(Material(5.0, 0.25), 0.08, Material(1.0, 0.35), Interface::frictionless);
  const double dx = 0.05;
  const double dy = 0.04;
  const InfluenceKernel big = split_frf_kernel(Grid(40, 40, 40 * dx, 40 * dy), frf);
  for (const auto& [nx, ny] : std::vector<std::pair<std::ptrdiff_t, std::ptrdiff_t>>{
           {1, 1}, {1, 7}, {7, 1}, {2, 3}, {9, 5}}) {
    INFO(nx << " x " << ny);
    const InfluenceKernel small = split_frf_kernel(
        Grid(nx, ny, static_cast<double>(nx) * dx, static_cast<double>(ny) * dy), frf);
    double worst = 0.0;
    for (std::ptrdiff_t j = 1 - ny; j < ny; ++j)
      for (std::ptrdiff_t i = 1 - nx; i < nx; ++i)
        worst = std::max(worst, std::abs(small.at(i, j) - big.at(i, j)));
    CHECK(small.wrapped().allFinite());
    CHECK(worst <= 1e-9 * big.at(0, 0));
  }
}

TEST_CASE("split kernel does not depend on the number of threads", "[split]") {
  // Every coefficient is computed by the same arithmetic whichever thread does it: identical.
  const CoatedFrf frf(Material(0.1, 0.3), 0.02, Material(1.0, 0.3), Interface::bonded);
  const Grid grid(19, 14, 1.9, 1.4);
  SplitKernelOptions threaded;
  threaded.threads = 3;
  CHECK(max_abs_difference(split_frf_kernel(grid, frf), split_frf_kernel(grid, frf, threaded)) ==
        0.0);
}

TEST_CASE("split kernel's quarter feeds DC-FFT like the direct sum of its wrap-around array",
          "[split]") {
  // The kernel is stored as its quarter: the wrap-around array must mirror it exactly, and
  // DcfftOperator built from it must equal the direct sum of the wrap-around coefficients on a
  // random load; square and elongated cells, a grid large enough for the stencil route
  // (N >= 290; its direct sum would take seconds, so only the mirror is checked there) and a
  // small one.
  const CoatedFrf frf(Material(600e9, 0.25), 50e-6, Material(210e9, 0.3), Interface::bonded);
  for (const Grid& grid : {Grid(300, 300, 4e-3, 4e-3), Grid(23, 17, 1e-3, 2e-3)}) {
    INFO(grid.nx() << " x " << grid.ny());
    const InfluenceKernel kernel = split_frf_kernel(grid, frf);
    REQUIRE(kernel.quarter().rows() == grid.nx() + 1);
    REQUIRE(kernel.quarter().cols() == grid.ny() + 1);
    const Field wrapped = kernel.wrapped();
    const std::ptrdiff_t mx = 2 * grid.nx(), my = 2 * grid.ny();
    double worst = 0.0;
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
        for (const double w : {wrapped(i, j), wrapped((mx - i) % mx, j), wrapped(i, (my - j) % my)})
          worst = std::max(worst, std::abs(kernel.quarter()(i, j) - w));
    CHECK(worst == 0.0);
    if (grid.nx() > 100) continue;
    Field p(grid.nx(), grid.ny());
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) p(i, j) = 1.0 + std::cos(0.7 * i + 1.3 * j);
    DcfftOperator dcfft(kernel);
    DirectOperator direct(kernel);
    const Field u = dcfft.apply(p);
    const Field v = direct.apply(p);
    // FFT round-off ~ eps log2(4 nx ny); 1e-12 is the project's tier for DC-FFT against direct.
    CHECK((u - v).abs().maxCoeff() <= 1e-12 * v.abs().maxCoeff());
  }
}

TEST_CASE("split kernel rejects bad options", "[split]") {
  const Grid grid(8, 8, 1.0, 1.0);
  const HalfSpaceFrf frf(Material(1.0, 0.3));
  SplitKernelOptions o;
  o.beta = -1.0;
  CHECK_THROWS_AS(split_frf_kernel(grid, frf, o), InvalidArgument);
  o = {};
  o.sigma = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(split_frf_kernel(grid, frf, o), InvalidArgument);
  o = {};
  o.tolerance = 0.0;
  CHECK_THROWS_AS(split_frf_kernel(grid, frf, o), InvalidArgument);
  o = {};
  o.threads = 0;
  CHECK_THROWS_AS(split_frf_kernel(grid, frf, o), InvalidArgument);
  o = {};
  o.max_alias_order = -1;
  CHECK_THROWS_AS(split_frf_kernel(grid, frf, o), InvalidArgument);
  CHECK_THROWS_AS(detail::split_rectangle_integral(0, 0, 1, 1, 0.0), InvalidArgument);
}

// ---- Elongated cells and domains: cost bounded by the grid, accuracy as for square cells ------
//
// The cases of the aspect-ratio benchmark (bench/bench_split_aspect.cpp): 24 x 24 cells on
// 2 mm x ly for ly up to 4096 m (cells up to 2e6 times longer than wide), and 1 x 4096 and
// 4096 x 1 cells on 2 mm x 2 mm (cells of 2 mm x 0.49 um). These take the wide-axis lattice, the
// logarithmic tail table and the graded cell rules (docs/split_kernel.md, section 7).

namespace {

struct Elongated {
  const char* what;
  Grid grid;
};

std::vector<Elongated> elongated_grids() {
  return {{"24 x 24 on 2 mm x 20 mm", Grid(24, 24, 2e-3, 2e-2)},
          {"24 x 24 on 2 mm x 0.2 m", Grid(24, 24, 2e-3, 0.2)},
          {"24 x 24 on 2 mm x 4096 m", Grid(24, 24, 2e-3, 4096.0)},
          {"1 x 4096 on 2 mm x 2 mm", Grid(1, 4096, 2e-3, 2e-3)},
          {"4096 x 1 on 2 mm x 2 mm", Grid(4096, 1, 2e-3, 2e-3)}};
}

// TiN (400 GPa, 0.25) 20 um bonded on steel (210 GPa, 0.3), the body of the benchmark.
CoatedFrf tin_on_steel() {
  return CoatedFrf(Material(400e9, 0.25), 20e-6, Material(210e9, 0.3), Interface::bonded);
}

}  // namespace

TEST_CASE("split kernel on elongated cells: a homogeneous body is Love's kernel", "[split]") {
  // R = 0: only the closed forms (a) remain, whatever the aspect ratio; as in the square test
  // above, only 2 / (2 / E*) differs from E* in the last bit.
  const Material steel(210e9, 0.3);
  const HalfSpaceFrf half(steel);
  const CoatedFrf same(steel, 20e-6, steel, Interface::bonded);
  for (const Elongated& e : elongated_grids()) {
    INFO(e.what);
    const InfluenceKernel love = love_kernel(e.grid, steel.plane_strain_modulus());
    for (const Frf* frf : std::vector<const Frf*>{&half, &same}) {
      SplitKernelReport report;
      const InfluenceKernel split = split_frf_kernel(e.grid, *frf, {}, &report);
      CHECK(report.remainder_zero);
      CHECK(max_abs_difference(split, love) <= 1e-14 * love.at(0, 0));
    }
  }
}

TEST_CASE("split kernel on elongated cells and domains reproduces the closed form", "[split]") {
  // As "split remainder reproduces the closed form" above (beta = 2.5 b, so that R is not zero
  // and must come out of the lattice and the Hankel part): b = 20 um, a layer 4 times thinner
  // than the short cell side and up to 1e7 times thinner than the long one, and b = 0.5 mm,
  // whose R reaches over many cells and into the logarithmic tail of the long part. Every
  // coefficient within 1e-9 of K(0, 0), the tolerance of the square cases (measured: <= 2.3e-10).
  // The Hankel table stays the same size for ly = 20 mm and 4096 m (the uniform table at
  // ly = 4096 m would have needed ~4e8 radii): its size is checked, not its time.
  for (const double b : {20e-6, 5e-4}) {
    const ExponentialFrf frf(3.0, 1.0, b);
    SplitKernelOptions off;
    off.beta = 2.5 * b;
    for (const Elongated& e : elongated_grids()) {
      INFO(e.what << ", b = " << b);
      SplitKernelReport report;
      const InfluenceKernel k = split_frf_kernel(e.grid, frf, off, &report);
      CHECK_FALSE(report.alias_capped);
      CHECK(report.hankel_r_points < 4000);
      const double dx = e.grid.dx();
      const double dy = e.grid.dy();
      const double k00 = closed_form(frf, b, 0.0, 0.0, dx, dy);
      double worst = 0.0;
      for (std::ptrdiff_t j = 0; j < e.grid.ny(); ++j)
        for (std::ptrdiff_t i = 0; i < e.grid.nx(); ++i) {
          const double ref =
              closed_form(frf, b, static_cast<double>(i) * dx, static_cast<double>(j) * dy, dx, dy);
          worst = std::max(worst, std::abs(k.at(i, j) - ref));
        }
      CHECK(worst <= 1e-9 * k00);
    }
  }
}

TEST_CASE("split kernel on elongated cells: a coated body agrees with the full alias fold",
          "[split]") {
  // TiN 20 um on steel. The automatic plan makes the long cell side a wide axis (no alias along
  // it); the reference folds every alias of that side instead (max_alias_order 4096, a sigma for
  // which the side is not wide, the uniform Hankel table only). 1e-9 of K(0, 0) as above
  // (measured: 9e-11).
  const CoatedFrf frf = tin_on_steel();
  SplitKernelOptions folded;
  folded.max_alias_order = 4096;
  SECTION("1 x 4096 cells of 2 mm x 0.49 um, and 4096 x 1 the same transposed") {
    const Grid grid(1, 4096, 2e-3, 2e-3);
    SplitKernelReport report;
    const InfluenceKernel k = split_frf_kernel(grid, frf, {}, &report);
    CHECK(report.wide_x);
    folded.sigma = 62.5e-6;
    SplitKernelReport ref_report;
    const InfluenceKernel ref = split_frf_kernel(grid, frf, folded, &ref_report);
    CHECK_FALSE(ref_report.wide_x);
    CHECK(ref_report.alias_order > 400);
    const InfluenceKernel t = split_frf_kernel(Grid(4096, 1, 2e-3, 2e-3), frf);
    double worst = 0.0;
    double transposed = 0.0;
    for (std::ptrdiff_t j = 0; j < 4096; ++j) {
      worst = std::max(worst, std::abs(k.at(0, j) - ref.at(0, j)));
      transposed = std::max(transposed, std::abs(k.at(0, j) - t.at(j, 0)));
    }
    CHECK(worst <= 1e-9 * k.at(0, 0));
    CHECK(transposed <= 1e-12 * k.at(0, 0));
  }
  SECTION("24 x 24 cells of 83 um x 8.3 mm against the same cells on a 24 x 2 grid") {
    const Grid grid(24, 24, 2e-3, 0.2);
    SplitKernelReport report;
    const InfluenceKernel k = split_frf_kernel(grid, frf, {}, &report);
    CHECK(report.wide_y);
    folded.sigma = 0.4e-3;
    SplitKernelReport ref_report;
    const InfluenceKernel ref =
        split_frf_kernel(Grid(24, 2, 2e-3, 0.2 / 12.0), frf, folded, &ref_report);
    CHECK_FALSE(ref_report.wide_y);
    CHECK(ref_report.alias_order > 1000);
    double worst = 0.0;
    for (std::ptrdiff_t j = -1; j <= 1; ++j)
      for (std::ptrdiff_t i = -23; i <= 23; ++i)
        worst = std::max(worst, std::abs(k.at(i, j) - ref.at(i, j)));
    CHECK(worst <= 1e-9 * k.at(0, 0));
  }
}

TEST_CASE("split kernel refuses a short-range lattice that cannot fit", "[split]") {
  // A sigma given by the caller sets the lattice's half period 32 sigma/d: 1 m against cells of
  // 16 um would need ~4e12 entries. Refused before any allocation, naming the cause.
  const Grid grid(64, 64, 1e-3, 1e-3);
  SplitKernelOptions o;
  o.sigma = 1.0;
  CHECK_THROWS_AS(split_frf_kernel(grid, tin_on_steel(), o), InvalidArgument);
  CHECK_THROWS_WITH(split_frf_kernel(grid, tin_on_steel(), o),
                    Catch::Matchers::Contains("short-range lattice"));
}
