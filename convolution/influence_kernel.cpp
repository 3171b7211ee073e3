#include "convolution/influence_kernel.hpp"

#include <cmath>
#include <utility>

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
  (void)threads;
  COATFFT_REQUIRE(std::isfinite(plane_strain_modulus) && plane_strain_modulus > 0,
                  "love_kernel: E* = ", plane_strain_modulus, " Pa, but E* must be finite and > 0");
  const std::ptrdiff_t nx = grid.nx();
  const std::ptrdiff_t ny = grid.ny();
  const double dx = grid.dx();
  const double dy = grid.dy();
  Field wrapped = Field::Zero(2 * nx, 2 * ny);
  // Love's coefficient is even in x and in y: evaluate the quarter di, dj >= 0 and mirror it, which
  // also makes the wrapped array exactly symmetric (DcfftOperator then stores a real spectrum).
  for (std::ptrdiff_t dj = 0; dj < ny; ++dj) {
    for (std::ptrdiff_t di = 0; di < nx; ++di) {
      const double k =
          love_influence(static_cast<double>(di) * dx, static_cast<double>(dj) * dy, dx, dy) /
          plane_strain_modulus;
      const std::ptrdiff_t mi = di == 0 ? 0 : 2 * nx - di;
      const std::ptrdiff_t mj = dj == 0 ? 0 : 2 * ny - dj;
      wrapped(di, dj) = k;
      wrapped(mi, dj) = k;
      wrapped(di, mj) = k;
      wrapped(mi, mj) = k;
    }
  }
  return InfluenceKernel(grid, std::move(wrapped));
}

}  // namespace coatfft
