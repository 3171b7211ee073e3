#pragma once
// The nine surface influence coefficients of a periodic surface: u_x, u_y, u_z at the cell centres
// under a unit pressure and unit tractions q_x, q_y uniform over the cell at the origin and over
// all its periodic images, for any bonded layer stack (docs/theory.md 4.8 and 2.9). Exact for a
// periodic problem: every FRF times the cell's transform on the period's lattice, every alias
// included. The k = 0 terms are left out, as for the normal displacement: a net force on a
// periodic surface moves it without bound, so every displacement has zero mean over the period.
//
// With theta the wavevector's direction, the FRFs are H_zz, S (radial), D cos 2theta,
// D sin 2theta and -i C cos theta, -i C sin theta (frf/traction_response.hpp):
//   H_zz and S by periodic_influence_kernel (convolution/kernels/periodic_kernel.hpp);
//   the angular ones split as X_inf a(theta)/k, the top medium's half-space, and the remainder
//   (X(k) - X_inf/k) a(theta), which decays like exp(-2 k h_top), on the lattice with its
//   aliases. X_inf a(theta)/k goes by Ewald's (1921) split, written for the derivatives of a
//   radial potential: a(theta)/k is (1/2pi)(d_xx - d_yy) r, (1/pi) d_xy r or (1/2pi) d_x ln r
//   in space; r = r erfc(alpha r) + r erf(alpha r) and ln r = -E1(alpha^2 r^2)/2 +
//   (ln r + E1(alpha^2 r^2)/2), the first parts short-ranged (their cell integrals: the closed
//   forms of angular_influence less Gauss-Legendre rules of the smooth second parts' derivatives),
//   the second ones' derivatives Gaussian-fast on the lattice.
#include "../../core/grid.hpp"
#include "../../layers/layer_stack.hpp"
#include "periodic_kernel.hpp"
#include "traction_kernels.hpp"

namespace coatfft {

/// The periodic coefficients K(i, j) [m/Pa], 0 <= i < nx, 0 <= j < ny, at the offset
/// (i dx, j dy) modulo the period, each with zero mean, with the names and parities of
/// TractionKernels (u_x, u_y under p by reciprocity: -zx, -zy). InvalidArgument for a stack with
/// a frictionless interface (no finite in-plane compliance), odd nx or ny, bad options, or
/// remainders too costly (options.max_evaluations).
TractionKernels periodic_traction_kernels(const Grid& grid, const LayerStack& stack,
                                          const PeriodicKernelOptions& options = {});

/// About how many FRF evaluations the angular remainders' lattice of periodic_traction_kernels
/// takes (0 for a homogeneous body; about 9 (L/h_top)^2 for a top coating h_top thick), to refuse
/// before any work what would exceed options.max_evaluations. InvalidArgument for a stack with a
/// frictionless interface.
double periodic_traction_kernel_evaluations(const Grid& grid, const LayerStack& stack,
                                            const PeriodicKernelOptions& options = {});

}  // namespace coatfft
