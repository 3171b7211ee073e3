#include "convolution/influence_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>
#include <vector>

#include "convolution/love_influence.hpp"
#include "core/error.hpp"

namespace coatfft {

InfluenceKernel::InfluenceKernel(const Grid& grid, Field wrapped)
    : grid_(grid), wrapped_(std::move(wrapped)) {
  COATFFT_REQUIRE(wrapped_.rows() == 2 * grid_.nx() && wrapped_.cols() == 2 * grid_.ny(),
                  "InfluenceKernel: wrapped array has shape (", wrapped_.rows(), ", ",
                  wrapped_.cols(), "), but the grid (", grid_.nx(), ", ", grid_.ny(),
                  ") needs (2 nx, 2 ny) = (", 2 * grid_.nx(), ", ", 2 * grid_.ny(), ")");
  COATFFT_REQUIRE(wrapped_.allFinite(), "InfluenceKernel: the coefficients must all be finite");
  wrapped_.row(grid_.nx()).setZero();
  wrapped_.col(grid_.ny()).setZero();
}

double InfluenceKernel::at(std::ptrdiff_t di, std::ptrdiff_t dj) const {
  const std::ptrdiff_t nx = grid_.nx();
  const std::ptrdiff_t ny = grid_.ny();
  COATFFT_REQUIRE(di > -nx && di < nx, "InfluenceKernel::at: di = ", di,
                  ", but |di| must be <= ", nx - 1);
  COATFFT_REQUIRE(dj > -ny && dj < ny, "InfluenceKernel::at: dj = ", dj,
                  ", but |dj| must be <= ", ny - 1);
  return wrapped_(di >= 0 ? di : 2 * nx + di, dj >= 0 ? dj : 2 * ny + dj);
}

InfluenceKernel wrap_even_kernel(const EvenInfluenceKernel& kernel) {
  const std::ptrdiff_t nx = kernel.grid.nx();
  const std::ptrdiff_t ny = kernel.grid.ny();
  const Field& q = kernel.quarter;
  COATFFT_REQUIRE(q.rows() == nx + 1 && q.cols() == ny + 1,
                  "wrap_even_kernel: the quarter has shape (", q.rows(), ", ", q.cols(),
                  "), but the grid needs (", nx + 1, ", ", ny + 1, ")");
  // Every entry written once: column dj of the quarter, mirrored within the column (slot
  // 2nx - di), copied to column 2ny - dj. The slots nx and ny are the unused zeros.
  const std::ptrdiff_t mx = 2 * nx;
  const std::ptrdiff_t my = 2 * ny;
  Field wrapped(mx, my);
  for (std::ptrdiff_t dj = 0; dj < ny; ++dj) {
    double* c = &wrapped(0, dj);
    std::copy_n(&q(0, dj), nx, c);
    c[nx] = 0.0;
    for (std::ptrdiff_t di = 1; di < nx; ++di) c[mx - di] = c[di];
    if (dj > 0) std::copy_n(c, mx, &wrapped(0, my - dj));
  }
  wrapped.col(ny).setZero();
  return InfluenceKernel(kernel.grid, std::move(wrapped));
}

EvenInfluenceKernel love_kernel_quarter(const Grid& grid, double plane_strain_modulus,
                                        int threads) {
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
  const auto workers = static_cast<std::ptrdiff_t>(std::min<std::ptrdiff_t>(threads, ny));
  if (workers <= 1) {
    for (std::ptrdiff_t dj = 0; dj < ny; ++dj) column(dj);
  } else {
    // Columns are interleaved between the workers: the far-field rule (and so the cost) changes
    // with dj, and interleaving balances it.
    std::vector<std::jthread> pool;
    for (std::ptrdiff_t w = 1; w < workers; ++w)
      pool.emplace_back([&column, w, workers, ny] {
        for (std::ptrdiff_t dj = w; dj < ny; dj += workers) column(dj);
      });
    for (std::ptrdiff_t dj = 0; dj < ny; dj += workers) column(dj);
  }
  quarter.col(ny).setZero();
  return {grid, std::move(quarter)};
}

InfluenceKernel love_kernel(const Grid& grid, double plane_strain_modulus, int threads) {
  return wrap_even_kernel(love_kernel_quarter(grid, plane_strain_modulus, threads));
}

}  // namespace coatfft
