#include <cmath>
#include <utility>

#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/love_influence.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/error.hpp"

namespace coatfft {

InfluenceKernel love_kernel(const Grid& grid, double plane_strain_modulus, int threads) {
  COATFFT_REQUIRE(std::isfinite(plane_strain_modulus) && plane_strain_modulus > 0,
                  "love_kernel: E* = ", plane_strain_modulus, " Pa, but E* must be finite and > 0");
  COATFFT_REQUIRE(threads >= 1, "love_kernel: threads = ", threads, ", but must be >= 1");
  const std::ptrdiff_t nx = grid.nx();
  const std::ptrdiff_t ny = grid.ny();
  const double dx = grid.dx();
  const double dy = grid.dy();
  const double inv_e = 1.0 / plane_strain_modulus;
  // Love's coefficient is even in x and in y: each column dj of the quarter is computed along x
  // in one vectorised run.
  Field quarter(nx + 1, ny + 1);
  const auto column = [&](std::ptrdiff_t dj) {
    double* c = &quarter(0, dj);
    detail::love_influence_row(static_cast<double>(dj) * dy, dx, dy, nx, c);
    for (std::ptrdiff_t di = 0; di < nx; ++di) c[di] *= inv_e;
    c[nx] = 0.0;
  };
  // Columns are interleaved between the workers: the far-field rule (and so the cost) changes
  // with dj, and interleaving balances it.
  detail::parallel_for(0, ny, threads, column);
  quarter.col(ny).setZero();
  return InfluenceKernel(grid, InfluenceKernel::Form::coefficients, std::move(quarter),
                         Method::dcfft);
}

}  // namespace coatfft
