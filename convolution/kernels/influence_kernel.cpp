#include "convolution/kernels/influence_kernel.hpp"

#include <algorithm>
#include <utility>

#include "core/error.hpp"

namespace coatfft {

InfluenceKernel::InfluenceKernel(const Grid& grid, Form form, Field quarter, Method method)
    : grid_(grid), form_(form), quarter_(std::move(quarter)), method_(method) {
  const char* what = form == Form::coefficients ? "coefficients" : "spectrum";
  COATFFT_REQUIRE(quarter_.rows() == grid_.nx() + 1 && quarter_.cols() == grid_.ny() + 1,
                  "InfluenceKernel: the ", what, " quarter has shape (", quarter_.rows(), ", ",
                  quarter_.cols(), "), but the grid needs (nx + 1, ny + 1) = (", grid_.nx() + 1,
                  ", ", grid_.ny() + 1, ")");
  COATFFT_REQUIRE(quarter_.allFinite(), "InfluenceKernel: the ", what,
                  " quarter is not finite (an entry is NaN or infinite)");
  if (form_ == Form::coefficients) {
    quarter_.row(grid_.nx()).setZero();
    quarter_.col(grid_.ny()).setZero();
  }
}

double InfluenceKernel::at(std::ptrdiff_t di, std::ptrdiff_t dj) const {
  const std::ptrdiff_t nx = grid_.nx();
  const std::ptrdiff_t ny = grid_.ny();
  COATFFT_REQUIRE(form_ == Form::coefficients,
                  "InfluenceKernel::at: the kernel is stored as its spectrum");
  COATFFT_REQUIRE(di > -nx && di < nx, "InfluenceKernel::at: di = ", di,
                  ", but |di| must be <= ", nx - 1);
  COATFFT_REQUIRE(dj > -ny && dj < ny, "InfluenceKernel::at: dj = ", dj,
                  ", but |dj| must be <= ", ny - 1);
  return quarter_(di >= 0 ? di : -di, dj >= 0 ? dj : -dj);
}

Field InfluenceKernel::wrapped() const {
  COATFFT_REQUIRE(form_ == Form::coefficients,
                  "InfluenceKernel::wrapped: the kernel is stored as its spectrum");
  // Every entry written once: column dj of the quarter, mirrored within the column (slot
  // 2nx - di), copied to column 2ny - dj. The slots nx and ny are the unused zeros.
  const std::ptrdiff_t nx = grid_.nx();
  const std::ptrdiff_t ny = grid_.ny();
  const std::ptrdiff_t mx = 2 * nx;
  const std::ptrdiff_t my = 2 * ny;
  Field w(mx, my);
  for (std::ptrdiff_t dj = 0; dj < ny; ++dj) {
    double* c = &w(0, dj);
    std::copy_n(&quarter_(0, dj), nx, c);
    c[nx] = 0.0;
    for (std::ptrdiff_t di = 1; di < nx; ++di) c[mx - di] = c[di];
    if (dj > 0) std::copy_n(c, mx, &w(0, my - dj));
  }
  w.col(ny).setZero();
  return w;
}

}  // namespace coatfft
