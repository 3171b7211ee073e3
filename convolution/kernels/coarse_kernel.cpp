#include "convolution/kernels/detail/coarse_kernel.hpp"

#include <cstdlib>

namespace coatfft::detail {

namespace {

// K_c(I, J) over an nx x ny coarse array from the fine coefficient at an offset, fine(di, dj).
template <class Fine>
Field galerkin_sum(std::ptrdiff_t nx, std::ptrdiff_t ny, Fine&& fine) {
  Field coarse(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      double sum = 0.0;
      for (int b = -1; b <= 1; ++b) {
        for (int a = -1; a <= 1; ++a) {
          sum += (2 - std::abs(a)) * (2 - std::abs(b)) * fine(2 * i + a, 2 * j + b);
        }
      }
      coarse(i, j) = 0.25 * sum;
    }
  }
  return coarse;
}

}  // namespace

Field coarse_periodic_kernel(const Field& kernel) {
  const auto nx = kernel.rows();
  const auto ny = kernel.cols();
  // The offsets reach one cell beyond either end: wrapped by a comparison, not a division (the
  // nine reads of each coarse cell would otherwise cost eighteen integer divisions).
  const auto wrap = [](std::ptrdiff_t d, std::ptrdiff_t n) {
    return d < 0 ? d + n : d >= n ? d - n : d;
  };
  return galerkin_sum(nx / 2, ny / 2, [&](std::ptrdiff_t di, std::ptrdiff_t dj) {
    return kernel(wrap(di, nx), wrap(dj, ny));
  });
}

Field coarse_periodic_kernel_rows(const Field& rows, const double* before) {
  const auto nx = rows.rows();
  const auto wrap = [nx](std::ptrdiff_t d) { return d < 0 ? d + nx : d >= nx ? d - nx : d; };
  // Coarse row J of the slab reads fine rows 2 J - 1 .. 2 J + 1: within the slab but for -1.
  return galerkin_sum(nx / 2, rows.cols() / 2, [&](std::ptrdiff_t di, std::ptrdiff_t dj) {
    return dj < 0 ? before[wrap(di)] : rows(wrap(di), dj);
  });
}

Field coarse_kernel_quarter(const Field& quarter) {
  const auto nx = quarter.rows() - 1;  // the fine grid's cells per side
  const auto ny = quarter.cols() - 1;
  Field coarse = Field::Zero(nx / 2 + 1, ny / 2 + 1);
  coarse.topLeftCorner(nx / 2, ny / 2) =
      galerkin_sum(nx / 2, ny / 2, [&](std::ptrdiff_t di, std::ptrdiff_t dj) {
        return quarter(std::abs(di), std::abs(dj));  // K(-d) = K(d)
      });
  return coarse;
}

}  // namespace coatfft::detail
