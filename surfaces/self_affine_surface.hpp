#pragma once
// Periodic, self-affine random surfaces (the topographies of rough-contact studies: Persson 2001,
// Hyun et al. 2004, Jacobs et al. 2017): a height field on the grid whose isotropic power spectrum
// is
//   C(q) = C0 (q / q_r)^(-2 (1 + H))   for q_r <= q <= q_s,   C0 for q < q_r (the roll-off),
//   0 for q > q_s,
// H the Hurst exponent, q_r = 2 pi / lambda_r and q_s = 2 pi / lambda_s the long and short cut-off
// wavevectors, and C0 set so that the rms height (or the rms slope) is the requested one exactly.
// Each Fourier mode has the amplitude sqrt(C(q)) exactly and a uniformly random phase from the
// seed (a random-phase surface: its spectrum is the requested one mode by mode, not only on
// average), zero mean, and is periodic over the domain. docs/surfaces.md.
#include <cstdint>
#include <optional>
#include <string_view>

#include "../core/grid.hpp"
#include "../core/types.hpp"

namespace coatfft {

struct SelfAffineSpec {
  double hurst = 0.8;  ///< H in (0, 1]
  /// Exactly one of the two: the rms height [m] or the rms slope [-] of the result (the slope of
  /// the trigonometric interpolant, sqrt(mean |grad h|^2), computed from the spectrum).
  std::optional<double> rms_height, rms_slope;
  /// lambda_s [m]: the shortest wavelength; default 2 max(dx, dy) (the grid's Nyquist).
  std::optional<double> short_cutoff;
  /// lambda_r [m]: the roll-off wavelength, beyond which the spectrum is flat; default
  /// max(lx, ly) (no roll-off: the longest wavelength of the domain).
  std::optional<double> long_cutoff;
  std::uint64_t seed = 0;  ///< the same seed gives the same surface (bit for bit)
};

/// The rms heights [m] a surface may have: from a femtometre (far below any measured roughness;
/// the spectrum's smallest modes stay normal doubles) to a metre (far above any contact
/// topography; squares and Fourier sums stay far from overflow). docs/surfaces.md, "Limits".
inline constexpr double min_rms_height = 1e-15, max_rms_height = 1.0;
/// The largest rms slope [-] (a mean inclination of 84 degrees: beyond any real surface).
inline constexpr double max_rms_slope = 10.0;

/// The largest cell count a side (a 16384^2 surface takes about 6 GiB while it is made), for
/// every front end: `coatfft surface --nx`, Python's self_affine_surface.
inline constexpr long max_surface_cells = 16384;

/// Refuses (InvalidArgument) what self_affine_surface would refuse: a side of more than
/// max_surface_cells cells, before any work: H outside
/// (0, 1], not exactly one rms, cut-offs not with 2 max(dx, dy) <= lambda_s < lambda_r, no mode
/// between the cut-offs, an rms height outside [min_rms_height, max_rms_height], an rms slope above
/// max_rms_slope or one whose surface would have an rms height outside that range (the ratio of
/// the two is fixed by the spectrum, not by the phases). The rms values are named `height_name`
/// and `slope_name` in the messages (the command line passes its flags).
void check_self_affine_spec(const Grid& grid, const SelfAffineSpec& spec,
                            std::string_view height_name = "the rms height",
                            std::string_view slope_name = "the rms slope");

/// Refuses (InvalidArgument naming `who`) a surface on `grid` that would not fit in the available
/// memory (core/memory.hpp), before anything is allocated: self_affine_surface asks it first, and
/// a front end may ask it before check_self_affine_spec, whose spectrum sums take time on the
/// largest grids.
void require_self_affine_memory(const Grid& grid, std::string_view who);

/// The surface h(x_i, y_j) [m], shape (nx, ny) of `grid` (both even, >= 2). InvalidArgument for
/// a bad spec (check_self_affine_spec).
Field self_affine_surface(const Grid& grid, const SelfAffineSpec& spec);

/// The spectral rms slope sqrt(mean |grad h|^2) of a periodic field on `grid` [-]: the slope of its
/// trigonometric interpolant (what self_affine_surface matches for rms_slope).
double spectral_rms_slope(const Grid& grid, const Field& h);

}  // namespace coatfft
