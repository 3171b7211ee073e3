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

InfluenceKernel love_kernel(const Grid& grid, double plane_strain_modulus, int threads) {
  COATFFT_REQUIRE(std::isfinite(plane_strain_modulus) && plane_strain_modulus > 0,
                  "love_kernel: E* = ", plane_strain_modulus, " Pa, but E* must be finite and > 0");
  COATFFT_REQUIRE(threads >= 1, "love_kernel: threads = ", threads, ", but must be >= 1");
  const std::ptrdiff_t nx = grid.nx();
  const std::ptrdiff_t ny = grid.ny();
  const std::ptrdiff_t mx = 2 * nx;
  const std::ptrdiff_t my = 2 * ny;
  const double dx = grid.dx();
  const double dy = grid.dy();
  const double inv_e = 1.0 / plane_strain_modulus;
  // Every entry is written exactly once (no zero fill of the (2nx, 2ny) array first). Love's
  // coefficient is even in x and in y: each column dj of the quarter di, dj >= 0 is computed
  // along x in one vectorised run, mirrored within the column (slot 2nx - di) and copied to
  // column 2ny - dj, which also makes the wrapped array exactly symmetric (DcfftOperator then
  // stores a real spectrum). The slots nx and ny are the unused zeros.
  Field wrapped(mx, my);
  const auto column = [&](std::ptrdiff_t dj) {
    double* c = &wrapped(0, dj);
    detail::love_influence_row(static_cast<double>(dj) * dy, dx, dy, nx, c);
    for (std::ptrdiff_t di = 0; di < nx; ++di) c[di] *= inv_e;
    c[nx] = 0.0;
    for (std::ptrdiff_t di = 1; di < nx; ++di) c[mx - di] = c[di];
    if (dj > 0) std::copy_n(c, mx, &wrapped(0, my - dj));
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
  wrapped.col(ny).setZero();
  return InfluenceKernel(grid, std::move(wrapped));
}

}  // namespace coatfft
