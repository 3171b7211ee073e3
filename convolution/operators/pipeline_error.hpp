#pragma once
// Error model of the FRF pipelines of Spinu (2021), frf-spectral and frf-dcfft (docs/theory.md
// 4.6). Their error is a periodisation (and Nyquist-sampling) error of the alpha-extended lattice:
// it falls with alpha, not with the number of cells, and grows with the anisotropy of the domain
// and of the cells. Because the half-space FRF 2/(E* k) has no length scale, the relative error
// for a homogeneous body is set by the shape of the problem alone (alpha, the domain's aspect
// ratio, the load's size in cells), so it is measured on a small proxy problem of the same shape,
// against Love's exact DC-FFT (Liu, Wang & Liu 2000; Love 1929), at a cost far below that of the
// operator on a large grid.
#include <cstddef>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../../frf/frf.hpp"
#include "../method.hpp"

namespace coatfft {

/// Predicted error of `method` (Method::frf_spectral or Method::frf_dcfft, with regularized or
/// converged g(0)) at domain extension ratio `alpha` on `grid`, for a homogeneous half-space:
///
///   max |u_pipeline - u_exact| / max |u_exact|   (the error measure of Spinu 2021, section 5)
///
/// under the reference load (pipeline_error_reference_load), u_exact being Love's DC-FFT
/// (docs/theory.md 4.6.1-4.6.2). It is measured on the proxy of pipeline_error_proxy, which is
/// `grid` itself when no cell is finer than min(lx, ly)/64 and the lattice fits the budget (64^2
/// cells up to alpha = 11): the value is then the measured error, to rounding. Throws
/// InvalidArgument for another method, or for an `alpha` that make_operator refuses on `grid`
/// (alpha < 1, or < 2 for frf-dcfft; alpha nx or alpha ny not a whole number). `threads` (>= 1)
/// as in make_operator; the value does not depend on it. Cost: building and applying the
/// pipeline and DC-FFT on the proxy, whose extended lattice holds about 2^19 points at most
/// (never over 2^20): about the operator's own cost where the grid is its own proxy, a few
/// percent of it on a 1024^2 grid.
double predicted_pipeline_error(const Grid& grid, Method method, double alpha, int threads = 1);

/// The same for the layered body of FRF `frf` (docs/theory.md 4.6.3): the pipeline with `frf` on
/// a proxy of at most 64 x 64 square cells against frf-split on the same proxy. A stiff coating
/// about as thick as the load's radius raises the error above the homogeneous value (up to 5.4x
/// measured), a soft one lowers it. The homogeneous prediction is returned instead where `frf` is
/// within 1 % of the substrate's C0/k up to 8/a (a half-space; a coating much thinner than the
/// load: the split kernel's ~10 ms are saved), where no such proxy fits (domains longer than
/// 64:1), and where `frf` cannot be split (c0 or c_inf not finite and positive) or the split
/// kernel of the proxy refuses it: the prediction is advice, and never fails for the body alone.
/// Same errors as above for the arguments; the FRF must be safe to call concurrently when
/// threads > 1 (every Frf of frf/ is).
double predicted_pipeline_error(const Grid& grid, const Frf& frf, Method method, double alpha,
                                int threads = 1);

/// The small problem on which the error of `grid` at `alpha` is measured: the same domain
/// (lx, ly), cells no smaller than min(lx, ly)/64 along either axis (an axis with coarser cells
/// keeps them, so a load that `grid` resolves poorly stays as poorly resolved), and about 2^19
/// points at most on the extended lattice of max(alpha, 2) (so also on DC-FFT's padded lattice):
/// beyond that budget both axes are coarsened by the same factor. Sizes below the grid's are
/// 7-smooth and of the grid's parity. `alpha` is kept when alpha times the proxy's sizes can be
/// whole numbers; otherwise (a denominator above 64) it is lowered to a multiple of 1/8, which
/// can only raise the predicted error. Throws InvalidArgument unless alpha is finite and >= 1.
struct PipelineErrorProxy {
  Grid grid;
  double alpha;
};
PipelineErrorProxy pipeline_error_proxy(const Grid& grid, double alpha);

/// The reference load of the model on `grid` [Pa]: a Hertz pressure sqrt(1 - r^2/a^2) of peak 1
/// and radius a = min(lx, ly)/3, centred on the domain (the configuration of Spinu 2021, L = 3a,
/// on the shorter side), averaged over each cell by a midpoint rule whose sub-intervals are at
/// most a/8 long, so that a load narrower than a cell is still applied with its force.
Field pipeline_error_reference_load(const Grid& grid);

}  // namespace coatfft
