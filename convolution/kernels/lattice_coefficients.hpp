#pragma once
// Cell-integrated influence coefficients of spectra that decay fast in k but reach far in space:
// the spectrum times the cell's transform, sampled on a lattice with every alias
// k + 2 pi (p/dx, q/dy) folded in (no truncation at Nyquist), brought to space by the parity
// transforms (DCT/DST). An Ewald-type split (convolution/kernels/detail/ewald_window.hpp) keeps the
// periodic images small: the short-range part F (1 - w) on DC-FFT's own lattice of period 2L, the
// band-limited long-range part F w on a lattice alpha times the domain (docs/theory.md 2.9.4).
// The stress kernels' lattices (stress/stress_kernel.cpp) work the same way for the planes at
// depth; this is the form for spectra given by a function of the wavevector.
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"

namespace coatfft {

struct LatticeSpectra {
  /// Per component: whether it is odd in kx and in ky (the coefficients then odd in x, y).
  std::vector<std::array<bool, 2>> parity;
  /// Beyond |k| > k_cut [rad/m] every spectrum is below the tolerance and left out.
  double k_cut = 0.0;
  /// Writes G_c = i^(odd_x + odd_y) F_c (real) of every component c at the wavevector (kx, ky),
  /// 0 < |k| = k <= k_cut, into out (parity.size() entries), F_c the spectrum [m/Pa]. The k = 0
  /// sample is taken as 0: the spectra must have a zero mean over the directions as k -> 0 (an
  /// angular factor cos(n theta), sin(n theta), n >= 1, times a bounded function). Called from
  /// several threads at once.
  std::function<void(double kx, double ky, double k, std::span<double> out)> sample;
};

struct LatticeOptions {
  int alpha = 16;                ///< period of the long-range lattice over the domain, >= 2
  int max_alias_order = 64;      ///< largest alias order |p|, |q| folded
  double max_evaluations = 2e8;  ///< most calls of sample (estimated first; InvalidArgument beyond)
  int threads = 1;               ///< threads of the lattice loop, in [1, max_threads]
};

struct LatticeReport {
  int alias_order = 0;
  bool alias_capped = false;  ///< the fold needed more than max_alias_order
  long long evaluations = 0;  ///< calls of sample
};

/// The wavenumber [rad/m] beyond which a spectrum bounded by a polynomial of degree <= 2 in k z
/// times exp(-k z) is below `tolerance` of its size: (ln(1/tol) + 2 ln(1 + ln(1/tol)) + 3)/z,
/// z > 0 [m] the decay length (the depth of a stress plane, a coating's thickness).
double exponential_cut_off(double z, double tolerance);

/// About how many calls of sample lattice_coefficients makes: the quarter disk |k| <= k_cut over
/// DC-FFT's lattice cell, at least the lattice quarter, plus the long-range band.
double lattice_evaluations(const Grid& grid, double k_cut, int alpha);

/// The coefficients K_c(i dx, j dy), 0 <= i < nx, 0 <= j < ny, of every component: K_c(x) =
/// (1/(4 pi^2)) \iint F_c(k) S(k) exp(i k.x) dk on the lattices above, S the cell's transform
/// over its area. InvalidArgument on bad options or an estimate beyond max_evaluations (named
/// `what` in the message).
std::vector<Field> lattice_coefficients(const Grid& grid, const LatticeSpectra& spectra,
                                        const LatticeOptions& options, const char* what,
                                        LatticeReport* report = nullptr);

}  // namespace coatfft
