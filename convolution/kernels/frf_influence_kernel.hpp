#pragma once
// Influence coefficients from an FRF (Spinu 2021, section 4, second algorithm;
// docs/theory.md 4.4; Liu & Wang, J. Tribol. 124 (2002) 36): the FRF is sampled on the frequency
// lattice of an alpha-times extended periodic domain, multiplied by the transform of a uniformly
// loaded cell, and brought back to space by an inverse FFT; the offsets |di| <= nx - 1,
// |dj| <= ny - 1 then feed DC-FFT (DcfftOperator). Used where no space-domain coefficient is known
// (coated and layered bodies); it inherits the periodicity error of the spectral pipeline.
#include "../../frf/frf.hpp"
#include "g0.hpp"
#include "influence_kernel.hpp"

namespace coatfft {

/// K(di, dj) = IFFT_M[ H(k) sinc(kx dx/2) sinc(ky dy/2) ] (docs/theory.md (4.1)) on the M = alpha N
/// lattice with H(0) = g(0) by `g0_method` to relative `g0_tolerance` [m/Pa]. alpha >= 2 with
/// alpha nx, alpha ny integers (so that offsets up to N - 1 are not wrapped onto each other);
/// throws InvalidArgument otherwise. If `g0_used` is given it receives the g(0) computed;
/// `threads` as in the overload below.
InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     G0Method g0_method, double g0_tolerance = default_g0_tolerance,
                                     G0Result* g0_used = nullptr, int threads = 1);

/// As above with a given g(0) (`g0.value` finite) instead of computing it; `threads` (>= 1)
/// threads sample the FRF (the Frf must be safe to call concurrently, as every Frf of frf/ is).
InfluenceKernel frf_influence_kernel(const Grid& grid, const Frf& frf, double alpha,
                                     const G0Result& g0, int threads = 1);

/// The kernel frf-dcfft runs on: frf_influence_kernel's coefficients, except at alpha = 2 (alpha
/// nx = 2 nx and alpha ny = 2 ny), where the extended lattice is DC-FFT's padded lattice and the
/// sampled spectrum H sinc sinc is returned directly in the spectrum form (no inverse and forward
/// transforms: the same operator to rounding, about a third less setup at 1024^2). The same
/// arguments and errors as frf_influence_kernel.
InfluenceKernel frf_dcfft_kernel(const Grid& grid, const Frf& frf, double alpha, const G0Result& g0,
                                 int threads = 1);

namespace detail {
/// H(k) sinc(kx dx/2) sinc(ky dy/2) on the quarter 0 <= jx <= mx/2, 0 <= jy <= my/2 of the
/// (mx, my) lattice of periods (mx dx, my dy), with g0.value at k = 0 (docs/theory.md (4.1) without
/// FFTW's 1/(mx my)); mx and my even. The spectrum behind frf_influence_kernel.
Field frf_cell_spectrum_quarter(const Grid& grid, const Frf& frf, std::ptrdiff_t mx,
                                std::ptrdiff_t my, const G0Result& g0, int threads);
}  // namespace detail

}  // namespace coatfft
