#pragma once
// Influence coefficients of the stresses on one plane z = const inside any layer stack: the six
// stresses at the cell centres (i dx, j dy, z) under a unit uniform load on the cell at the origin
// (a cell-integrated load, not a point load), for pressure and, when asked, the tractions q_x,
// q_y. They come from the stress FRFs of docs/theory.md 2.7 (frf/stress_frf.hpp) sampled on the
// lattice of an alpha-times extended period, times the cell's transform, with every alias
// k + 2 pi (p/dx, q/dy) folded in up to the tolerance (no truncation at Nyquist), and brought to
// space by a DCT/DST (docs/theory.md 2.8). The k = 0 sample is the FRF's mean over directions.
// What remains is the periodisation of the kernel's far field by the images at distances >=
// (alpha - 1) L, made small by a large alpha at little cost through an Ewald-type split.
#include <array>
#include <span>
#include <vector>

#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "../frf/layer_modes.hpp"
#include "../layers/layer_stack.hpp"

namespace coatfft {

struct StressKernelOptions {
  /// Period of the sampling lattice over the domain length, an integer >= 2 (2 is DC-FFT's own
  /// padded lattice; the periodic images' error falls like alpha^-3, docs/theory.md 2.8). Above
  /// 2 only the band-limited long-range part is sampled on it (about (34 alpha)^2 points).
  int alpha = 16;
  /// Relative size [-] of the FRF terms left out of the alias series; in (0, 1e-3].
  double tolerance = 1e-12;
  /// Largest alias order |p|, |q| folded (>= 0). Planes much shallower than a cell need
  /// about dx/z orders; at z = 0 the series is cut here (see report).
  int max_alias_order = 64;
  /// Most FRF evaluations a call may make (estimated before any work from the shallowest plane,
  /// about 111 (L/z)^2 at the default tolerance; InvalidArgument beyond). At 1 us each, the
  /// default is a few minutes. z = 0 is always refused: its alias series does not decay.
  double max_evaluations = 2e8;
  /// Threads of the lattice loop, in [1, max_threads]; the result does not depend on it.
  int threads = 1;
};

/// What stress_plane_kernel did.
struct StressKernelReport {
  int alias_order = 0;            ///< largest alias order folded
  bool alias_capped = false;      ///< the series needed more than max_alias_order
  long long frf_evaluations = 0;  ///< LayerModes solves of the call (shared by its planes)
  double seconds = 0.0;           ///< wall-clock time [s]
};

/// The coefficients of one plane. coefficients[c][l] holds K(i dx, j dy) for 0 <= i < nx,
/// 0 <= j < ny [Pa per Pa of load] of stress component c (StressComponent order xx, yy, zz, yz,
/// xz, xy) under load l (SurfaceLoad order p, q_x, q_y); the other quadrants follow from the
/// parity stress_frf_odd(c, l). Loads not built are empty arrays.
struct StressPlaneKernel {
  double depth = 0.0;
  std::array<std::array<Field, 3>, 6> coefficients;
};

/// The kernel of the plane at `depth` [m] (finite, > 0; on an interface, as LayerStack::locate
/// finds it, in the medium `side` names) of the body `stack`, on `grid`, for the pressure and, if
/// `tangential`, the tractions. Throws InvalidArgument on bad options or depth, and for a plane so
/// shallow against the domain that it would need more than options.max_evaluations FRF evaluations
/// (z = 0 always). The kernels of several planes at once: one LayerModes solve per wavevector
/// serves every plane (the cost is about that of the shallowest plane; the memory grows with the
/// planes). The same arguments and errors as stress_plane_kernel; `reports`, when given, gets one
/// per plane.
std::vector<StressPlaneKernel> stress_plane_kernels(
    const Grid& grid, const LayerStack& stack, std::span<const double> depths, InterfaceSide side,
    bool tangential, const StressKernelOptions& options = {},
    std::vector<StressKernelReport>* reports = nullptr);

/// About how many LayerModes solves stress_plane_kernels makes for `depths` (its cost: about a
/// microsecond each for one coating), from the shallowest plane; +inf for z = 0. Throws
/// InvalidArgument on bad options or depths, as stress_plane_kernels.
double stress_kernel_evaluations(const Grid& grid, std::span<const double> depths,
                                 const StressKernelOptions& options = {});

/// The kernels of a periodic surface's planes, given by their spectra on the period's own lattice
/// k = 2 pi (i/lx, j/ly), 0 <= i <= nx/2, 0 <= j <= ny/2: quarters[c][l](i, j) = i^(odd_x + odd_y)
/// F(k) (real; the parity of stress_frf_odd(c, l)), F the FRF of docs/theory.md 2.7 times the
/// cell's transform with every alias k + 2 pi (p/dx, q/dy) folded in: exact for cell-wise
/// constant loads repeated over the periods, nothing periodised twice (no alpha). The k = 0 entry
/// is the FRF's mean over the directions (stress_frf_at_zero): the mean stress under the mean
/// loads, that at depth under the centre of a uniformly loaded disc much wider than the depth
/// (docs/stress.md, "Periodic surfaces"). Arguments, errors and reports as stress_plane_kernels;
/// options.alpha is not used.
struct StressPlaneSpectrum {
  double depth = 0.0;
  std::array<std::array<Field, 3>, 6> quarters;
};

std::vector<StressPlaneSpectrum> periodic_stress_spectra(
    const Grid& grid, const LayerStack& stack, std::span<const double> depths, InterfaceSide side,
    bool tangential, const StressKernelOptions& options = {},
    std::vector<StressKernelReport>* reports = nullptr);

/// About how many LayerModes solves periodic_stress_spectra makes for `depths`: the quarter disk
/// |k| <= k_cut of the shallowest plane over the period's lattice cell, at least the lattice
/// quarter; +inf for z = 0.
double periodic_stress_evaluations(const Grid& grid, std::span<const double> depths,
                                   const StressKernelOptions& options = {});

StressPlaneKernel stress_plane_kernel(const Grid& grid, const LayerStack& stack, double depth,
                                      InterfaceSide side, bool tangential,
                                      const StressKernelOptions& options = {},
                                      StressKernelReport* report = nullptr);

}  // namespace coatfft
