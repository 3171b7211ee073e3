#pragma once
// The 2-D discrete Fourier transform of a real sequence that is even or odd along each axis, from
// its non-negative quarter: a DCT-I along an even axis and a DST-I along an odd one (FFTW's
// REDFT00 and RODFT00). The stress kernels of a plane are all of this kind (frf/stress_frf.hpp,
// stress_frf_odd), so their lattices and spectra are stored and transformed as real quarters.
#include "../../core/types.hpp"

namespace coatfft {

/// For f on the (mx, my) lattice (mx = 2 (quarter.rows() - 1), my likewise, both >= 2), even or
/// odd along x and y, given by quarter(jx, jy) = f(jx, jy), 0 <= jx <= mx/2, 0 <= jy <= my/2:
/// returns g with   sum_{jx, jy over the full lattice} f(jx, jy) exp(s i 2 pi (jx kx/mx + jy
/// ky/my)) = (s i)^(odd_x + odd_y) g(kx, ky) for 0 <= kx <= mx/2, 0 <= ky <= my/2, s = +1 or -1
/// (the transform is real either way). The entries of an odd axis at 0 and m/2 are ignored and
/// returned as 0.
Field parity_transform(const Field& quarter, bool odd_x, bool odd_y);

}  // namespace coatfft

namespace coatfft {

/// parity_transform's g at 0 <= kx < nx, 0 <= ky < ny only, for an f that vanishes beyond the
/// band 0 <= jx < band.rows(), 0 <= jy < band.cols() of its quarter (band.rows() <= mx/2,
/// band.cols() <= my/2: the Nyquist entries are 0), by two matrix products: about
/// band.rows() band.cols() nx + band.cols() nx ny operations and no (mx/2 + 1)(my/2 + 1) array.
Field band_parity_transform(const Field& band, bool odd_x, bool odd_y, std::ptrdiff_t mx,
                            std::ptrdiff_t my, std::ptrdiff_t nx, std::ptrdiff_t ny);

}  // namespace coatfft
