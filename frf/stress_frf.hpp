#pragma once
// The 3-D stress and displacement FRFs at depth of any layer stack (docs/theory.md 2.7, table
// T4): the mode fields of LayerModes, given along k (L) and across it (T), rotated to x, y. Per
// unit transform of each surface load -- pressure p, tractions q_x, q_y -- the transforms of the
// six stresses and three displacements at wavevector k = |k| (cx, cy), forward transform
// exp(-i k.x). Pressure positive in compression; stresses tension positive, z into the body.
#include <array>
#include <complex>

#include "layer_modes.hpp"

namespace coatfft {

/// Stress components in the order of stress.npy: xx, yy, zz, yz, xz, xy.
enum StressComponent { s_xx = 0, s_yy = 1, s_zz = 2, s_yz = 3, s_xz = 4, s_xy = 5 };
/// Surface loads: pressure (compression positive) and the tractions the surface receives.
enum SurfaceLoad { load_p = 0, load_qx = 1, load_qy = 2 };

struct StressFrf {
  /// stress[c][l]: transform of stress component c [Pa] per unit transform of load l [Pa].
  std::array<std::array<std::complex<double>, 3>, 6> stress{};
  /// displacement[d][l]: transform of u_x, u_y, u_z [m] per unit transform of load l [Pa].
  std::array<std::array<std::complex<double>, 3>, 3> displacement{};
};

/// T4 at direction (cx, cy) = k/|k| (cx^2 + cy^2 = 1) from the mode fields `m` at that |k|.
StressFrf stress_frf(const ModeFields& m, double cx, double cy);

/// The value an FFT lattice takes at k = 0, where T4 depends on the direction: its mean over the
/// directions (docs/theory.md 2.7), from the mode fields `m0` at a wavenumber small enough to be
/// the limit k -> 0+. The angular mean of cx^2 and cy^2 is 1/2, of odd products 0.
StressFrf stress_frf_at_zero(const ModeFields& m0);

/// Whether T4's entry for stress component c and load l changes sign with kx (first) and ky
/// (second): odd in kx when the indices x of the component and of the load number an odd count.
std::array<bool, 2> stress_frf_odd(int component, int load);

}  // namespace coatfft
