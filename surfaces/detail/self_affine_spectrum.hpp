#pragma once
// The random half spectrum of self_affine_surface, row by row, for callers that make the whole
// surface or one rank's rows of it (distributed/self_affine_slab.hpp): the same numbers for the
// same seed, however the rows are shared out.
#include <complex>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "surfaces/self_affine_surface.hpp"

namespace coatfft::detail {

/// Rows j0 <= j < j1 of the unscaled half spectrum (FFTW's r2c layout, nx/2 + 1 entries a row,
/// entry (i, j) at (j - j0)(nx/2 + 1) + i). The spec must have passed check_self_affine_spec.
void self_affine_rows(const Grid& grid, const SelfAffineSpec& spec, std::ptrdiff_t j0,
                      std::ptrdiff_t j1, std::complex<double>* rows);

/// One mode's part of the mean square slope times the cell count squared, weight |k|^2 |h_k|^2
/// for an unnormalised DFT coefficient h_k (weight 2 for the modes whose conjugate the half
/// spectrum leaves out): spectral_rms_slope sums them.
double mode_slope2(const Grid& grid, std::ptrdiff_t i, std::ptrdiff_t j, std::complex<double> h_k);

/// The unscaled field's mean squares of height and slope, or one row's part of them.
struct SpectrumMoments {
  double height2 = 0.0, slope2 = 0.0;
};

/// Rows j0 <= j < j1's parts, one a row (InvalidArgument for a spectrum self_affine_surface
/// refuses).
std::vector<SpectrumMoments> self_affine_row_moments(const Grid& grid, const SelfAffineSpec& spec,
                                                     std::ptrdiff_t j0, std::ptrdiff_t j1);

/// The factor that scales the unscaled field to the spec's rms, from every row's moments summed
/// in row order (the same sum however the rows were shared out), after the checks of
/// check_self_affine_spec (InvalidArgument, naming the rms as given).
double self_affine_scale(const SelfAffineSpec& spec, std::span<const SpectrumMoments> rows,
                         std::string_view height_name = "the rms height",
                         std::string_view slope_name = "the rms slope");

}  // namespace coatfft::detail
