#include "stress/parity_transform.hpp"

#include <cstddef>

#include "convolution/fftw_plan.hpp"
#include "core/error.hpp"

namespace coatfft {

Field parity_transform(const Field& quarter, bool odd_x, bool odd_y) {
  const std::ptrdiff_t hx = quarter.rows();
  const std::ptrdiff_t hy = quarter.cols();
  if (hx < 2 || hy < 2) throw InvalidArgument("parity_transform: a quarter needs 2 x 2 entries");
  // An even axis keeps the m/2 + 1 entries 0..m/2 (DCT-I), an odd one the m/2 - 1 entries
  // 1..m/2 - 1 (DST-I): its entries at 0 and m/2 are zero by symmetry.
  const std::ptrdiff_t first_x = odd_x ? 1 : 0;
  const std::ptrdiff_t first_y = odd_y ? 1 : 0;
  const std::ptrdiff_t nx = odd_x ? hx - 2 : hx;
  const std::ptrdiff_t ny = odd_y ? hy - 2 : hy;
  Field out = Field::Zero(hx, hy);
  if (nx == 0 || ny == 0) return out;

  FftwRealBuffer buffer(static_cast<std::size_t>(nx * ny));
  double* b = buffer.data();
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) b[j * nx + i] = quarter(first_x + i, first_y + j);
  // FFTW's row-major dimensions are {y, x}: x is the fastest index, as in a Field. A length-1
  // DCT-I is undefined in FFTW; the quarters here have >= 2 entries along even axes.
  const fftw_r2r_kind kinds[2] = {odd_y ? FFTW_RODFT00 : FFTW_REDFT00,
                                  odd_x ? FFTW_RODFT00 : FFTW_REDFT00};
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_r2r_2d(static_cast<int>(ny), static_cast<int>(nx), b, b, kinds[0], kinds[1],
                            FFTW_ESTIMATE);
  });
  plan.execute();
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) out(first_x + i, first_y + j) = b[j * nx + i];
  return out;
}

}  // namespace coatfft
