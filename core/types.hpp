#pragma once
// Field types. A Field is Eigen::ArrayXXd of shape (nx, ny), column-major, so x is the fastest
// index: field(i, j) is the value at (x_i, y_j) and the memory layout equals a C-order (ny, nx)
// array with row j = y_j -- exactly what FFTW (row-major, dimensions {ny, nx}) and .npy expect.
#include <Eigen/Core>
#include <complex>

namespace coatfft {

using Real = double;
using Complex = std::complex<double>;
using Field = Eigen::ArrayXXd;          // (nx, ny), x fastest
using ComplexField = Eigen::ArrayXXcd;  // (nx/2+1, ny) for an r2c half spectrum

}  // namespace coatfft
