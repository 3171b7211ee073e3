// The preconditioner of the contact iteration (contact/detail/fourier_preconditioner.hpp): |k| and
// the operator-adapted symbol.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "contact/detail/fourier_preconditioner.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/grid.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

using namespace coatfft;

TEST_CASE("Fourier preconditioner multiplies a plane wave by |k|", "[contact][preconditioner]") {
  const Grid grid(16, 12, 2.0e-3, 1.5e-3);  // non-square cells, even and non-power-of-2 sizes
  detail::FourierPreconditioner precond(grid);
  // (m, n) = wave numbers in periods per domain, including Nyquist along x (m = 8).
  for (const auto& [m, n] : {std::pair{1, 0}, {0, 2}, {3, -2}, {8, 5}}) {
    const double kx = 2 * std::numbers::pi * m / grid.lx();
    const double ky = 2 * std::numbers::pi * n / grid.ly();
    Field f(grid.nx(), grid.ny());
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j) {
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
        f(i, j) = std::cos(kx * grid.x(i) + ky * grid.y(j) + 0.3);
      }
    }
    Field g = f;
    precond.apply(g);
    const double k = std::hypot(kx, ky);
    INFO("m = " << m << ", n = " << n);
    // A plane wave is an eigenvector of a Fourier multiplier; FFT rounding is ~1e-15 relative.
    CHECK((g - k * f).abs().maxCoeff() <= 1e-12 * k);
  }
}

TEST_CASE("Fourier preconditioner: zero mode and symmetry", "[contact][preconditioner]") {
  const Grid grid(8, 8, 1.0, 1.0);
  detail::FourierPreconditioner precond(grid);
  Field c = Field::Constant(8, 8, 2.0);
  precond.apply(c);
  // sigma(0) = 1 / mean(1/|k|) over the central cell = dk / (4 asinh 1) = 2 pi / 3.525494348
  // (docs/theory.md 3.1, square cell).
  CHECK(c(3, 5) == Approx(2.0 * 2 * std::numbers::pi / 3.525494348).epsilon(1e-9));
  CHECK((c - c(0, 0)).abs().maxCoeff() <= 1e-13);
  // Symmetric positive definite: <a, M b> = <M a, b>, <a, M a> > 0.
  Field a(8, 8);
  Field b(8, 8);
  for (std::ptrdiff_t j = 0; j < 8; ++j) {
    for (std::ptrdiff_t i = 0; i < 8; ++i) {
      a(i, j) = std::sin(1.7 * i + 0.3 * j * j);
      b(i, j) = std::cos(0.4 * i * j + 2.1 * j);
    }
  }
  Field ma = a;
  Field mb = b;
  precond.apply(ma);
  precond.apply(mb);
  CHECK((a * mb).sum() == Approx((ma * b).sum()).epsilon(1e-12));
  CHECK((a * ma).sum() > 0);
}

TEST_CASE("The operator-adapted symbol is sqrt(|k| / K^), K^ the operator's own eigenvalue",
          "[contact][preconditioner]") {
  // A stiff thin coating on steel, periodic: a plane wave is an eigenvector of the operator and
  // of the preconditioner. The reference eigenvalue is measured by applying the operator to the
  // wave (independent of the kernel's DFT that adapt_to_kernel takes).
  const Grid grid(16, 12, 2.0e-4, 1.5e-4);
  const LayerStack stack({Coating{Material(210e12, 0.3), 2e-6}}, Material(210e9, 0.3));
  PeriodicOperator op(grid, periodic_influence_kernel(grid, *make_frf(stack)), Method::frf_split);
  detail::FourierPreconditioner precond(grid);
  REQUIRE(precond.adapt_to_kernel(op.unit_response()));
  for (const auto& [m, n] : {std::pair{1, 0}, {0, 2}, {3, -2}, {8, 5}}) {
    const double kx = 2 * std::numbers::pi * m / grid.lx();
    const double ky = 2 * std::numbers::pi * n / grid.ly();
    Field f(grid.nx(), grid.ny());
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
        f(i, j) = std::cos(kx * grid.x(i) + ky * grid.y(j) + 0.3);
    const double eigenvalue = (f * op.apply(f)).sum() / (f * f).sum();
    const double k = std::hypot(kx, ky);
    const double sigma = std::sqrt(k / eigenvalue);
    Field g = f;
    precond.apply(g);
    INFO("m = " << m << ", n = " << n << ", k K^ = " << k * eigenvalue);
    // FFT rounding is ~1e-15 relative; the eigenvalue's quotient adds as much.
    CHECK((g - sigma * f).abs().maxCoeff() <= 1e-12 * sigma);
  }
}
