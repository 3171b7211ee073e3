#pragma once
// The nine surface influence coefficients of any bonded layer stack: u_x, u_y, u_z at the cell
// centres under a unit pressure and unit tractions q_x, q_y uniform over one cell (docs/theory.md
// 2.9). The homogeneous half-space has them in closed form (Love 1929, Cerruti 1882:
// convolution/kernels/love_influence.hpp, cerruti_influence.hpp). A layered body splits each of its
// four surface FRFs (frf/traction_response.hpp) like frf-split splits H_zz:
//   f(k) = f_inf/k + (f_0 - f_inf) exp(-beta k)/k + R_f(k),
// f_inf the top medium's half-space, f_0 the substrate's, beta the top coating's thickness.
// The radial ones, H_zz and S, go through frf-split itself
// (convolution/kernels/split_frf_kernel.hpp); the angular ones, D cos 2theta, D sin 2theta and C
// cos theta, take their first two terms and R's limit at k = 0 (times exp(-beta k)) in closed form
// (convolution/kernels/angular_influence.hpp), and the rest of R, which vanishes at k = 0 and
// decays like exp(-k h_top), on the lattices of convolution/kernels/lattice_coefficients.hpp.
#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../../layers/layer_stack.hpp"
#include "lattice_coefficients.hpp"
#include "split_frf_kernel.hpp"

namespace coatfft {

/// The coefficients K(i dx, j dy), 0 <= i < nx, 0 <= j < ny, [m/Pa]: "zp" u_z under p (even,
/// even), "xx" u_x under q_x (even, even), "yy" u_y under q_y (even, even), "yx" u_y under q_x =
/// u_x under q_y (odd, odd), "zx" u_z under q_x (odd in x), "zy" u_z under q_y (odd in y). Under a
/// pressure, u_x and u_y follow by reciprocity: K_xp(d) = -K_zx(d), K_yp(d) = -K_zy(d).
struct TractionKernels {
  Field zp, xx, yy, yx, zx, zy;
};

struct TractionKernelOptions {
  SplitKernelOptions split;  ///< for H_zz and S (threads are taken from `lattice`)
  LatticeOptions lattice;    ///< for the remainders of D and C
  /// Relative size [-] of the remainder terms left out beyond the lattice's cut-off; (0, 1e-3].
  double tolerance = 1e-12;
};

struct TractionKernelReport {
  double beta = 0.0;      ///< transition length [m] (the top coating's thickness; 0: homogeneous)
  LatticeReport lattice;  ///< the remainders' lattices
  double seconds = 0.0;   ///< wall-clock time [s]
};

/// The kernels of `stack` on `grid`. Throws InvalidArgument for a stack with a frictionless
/// interface (no finite in-plane compliance as k -> 0: the coating slides), on bad options, and
/// when the remainders' lattice would exceed options.lattice.max_evaluations (a top coating very
/// thin against the domain: about 111 (L/h)^2 evaluations).
TractionKernels traction_kernels(const Grid& grid, const LayerStack& stack,
                                 const TractionKernelOptions& options = {},
                                 TractionKernelReport* report = nullptr);

/// About how many FRF evaluations the remainders' lattices of traction_kernels take for `stack` on
/// `grid` (0 for a homogeneous body), to refuse before any work what would exceed
/// options.lattice.max_evaluations.
double traction_kernel_evaluations(const Grid& grid, const LayerStack& stack,
                                   const TractionKernelOptions& options = {});

}  // namespace coatfft
