#include "convolution/fft/parity_transform.hpp"

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "convolution/fft/detail/fftw_plan.hpp"
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

namespace coatfft {

namespace {

// The matrix of one axis: phi(k, j) = w_j cos(2 pi j k/m) (even) or w_j sin(2 pi j k/m) (odd),
// w_0 = 1 and w_j = 2 otherwise: the two-sided sum folded onto j >= 0, as DCT-I/DST-I do.
Eigen::MatrixXd axis_matrix(std::ptrdiff_t outputs, std::ptrdiff_t band, std::ptrdiff_t m,
                            bool odd) {
  Eigen::MatrixXd phi(outputs, band);
  for (std::ptrdiff_t j = 0; j < band; ++j)
    for (std::ptrdiff_t k = 0; k < outputs; ++k) {
      // The phase j k mod m keeps the argument below 2 pi, where sin and cos are exact.
      const double angle =
          2.0 * 3.14159265358979323846 * static_cast<double>((j * k) % m) / static_cast<double>(m);
      const double w = j == 0 ? 1.0 : 2.0;
      phi(k, j) = odd ? (j == 0 ? 0.0 : w * std::sin(angle)) : w * std::cos(angle);
    }
  return phi;
}

}  // namespace

Field band_parity_transform(const Field& band, bool odd_x, bool odd_y, std::ptrdiff_t mx,
                            std::ptrdiff_t my, std::ptrdiff_t nx, std::ptrdiff_t ny) {
  if (band.rows() > mx / 2 || band.cols() > my / 2 || band.size() == 0)
    throw InvalidArgument("band_parity_transform: the band must lie below the Nyquist entries");
  const Eigen::MatrixXd phi_x = axis_matrix(nx, band.rows(), mx, odd_x);
  const Eigen::MatrixXd phi_y = axis_matrix(ny, band.cols(), my, odd_y);
  const Eigen::MatrixXd t = phi_x * band.matrix();  // (nx, band y)
  return (t * phi_y.transpose()).array();
}

}  // namespace coatfft
