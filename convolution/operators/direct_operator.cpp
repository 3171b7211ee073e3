#include "convolution/operators/detail/direct_operator.hpp"

#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft {

DirectOperator::DirectOperator(const InfluenceKernel& kernel)
    : grid_(kernel.grid()), wrapped_(kernel.wrapped()) {}

void DirectOperator::apply(const Field& pressure, Field& displacement) {
  const std::ptrdiff_t nx = grid().nx();
  const std::ptrdiff_t ny = grid().ny();
  COATFFT_REQUIRE(pressure.rows() == nx && pressure.cols() == ny,
                  "DirectOperator::apply: pressure has shape (", pressure.rows(), ", ",
                  pressure.cols(), "), but the grid needs (", nx, ", ", ny, ")");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "DirectOperator::apply: displacement must not alias pressure");
  const Field& w = wrapped_;
  displacement.resize(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    check_interrupt();  // (nx ny)^2 products: a large grid takes seconds
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      double sum = 0.0;
      for (std::ptrdiff_t l = 0; l < ny; ++l) {
        const std::ptrdiff_t dj = j - l;
        const std::ptrdiff_t sj = dj >= 0 ? dj : 2 * ny + dj;
        for (std::ptrdiff_t k = 0; k < nx; ++k) {
          const std::ptrdiff_t di = i - k;
          sum += w(di >= 0 ? di : 2 * nx + di, sj) * pressure(k, l);
        }
      }
      displacement(i, j) = sum;
    }
  }
}

}  // namespace coatfft
