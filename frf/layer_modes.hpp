#pragma once
// The fields at depth of a layered half-space for one Fourier mode (docs/theory.md §2.7): the
// displacements and all stresses inside any layer stack per unit surface load, from the global
// matrix of docs/theory.md §2.4 (alternative 1). Thick coatings (k h > 1) and the substrate carry
// the local decaying pairs of §2.1, thin coatings their state at the mid-plane, so that only
// factors <= 1 appear (nothing overflows for any k h) and a thin layer's response is not formed
// from rounded exponentials.
#include <span>
#include <vector>

#include "../layers/layer_stack.hpp"

namespace coatfft {

/// The real mode coefficients at depth z of docs/theory.md 2.7 for one wavenumber k > 0: per unit
/// pressure p (uL_p, uz_p, szz_p, sLz_p, sLL_p, sTT_p), per unit in-plane traction along k
/// (same names with _q; the real variables -i u_L etc. of 2.1), and the anti-plane (SH) mode per
/// unit q_T (uT_t, sTz_t, sLT_t). Stresses tension positive, z into the body.
///
/// Displacements in m/Pa, stresses in Pa/Pa. The physical mode fields (L along k, T across it,
/// forward transform exp(-i k.x)) are, per unit p: u_L = i uL_p, u_z = uz_p, sigma_zz = szz_p,
/// sigma_Lz = i sLz_p, sigma_LL = sLL_p, sigma_TT = sTT_p; per unit q_L: u_L = uL_q,
/// u_z = -i uz_q, sigma_zz = -i szz_q, sigma_Lz = sLz_q, sigma_LL = -i sLL_q, sigma_TT = -i sTT_q;
/// per unit q_T: u_T = uT_t, sigma_Tz = sTz_t, sigma_LT = i sLT_t. The components not listed are 0.
/// At z = 0, uL_q, uz_q (= uL_p) and uz_p are the surface compliance M of
/// MultilayerFrf::surface_compliance, and uz_p is the Frf H_zz(k).
struct ModeFields {
  double uL_p, uz_p, szz_p, sLz_p, sLL_p, sTT_p, uL_q, uz_q, szz_q, sLz_q, sLL_q, sTT_q, uT_t,
      sTz_t, sLT_t;
};

namespace detail {
/// One medium of a LayerModes stack (a coating, or the substrate with thickness +inf).
struct ModeMedium {
  double top;        ///< depth of its top face [m]
  double thickness;  ///< [m]; +inf for the substrate
  double nu;
  double mu;                  ///< shear modulus [Pa]
  Interface interface_below;  ///< unused for the substrate
};
}  // namespace detail

class LayerModes {
 public:
  /// Any stack (a homogeneous one included).
  explicit LayerModes(const LayerStack& stack);

  /// The coefficients at every depth of `depths` [m] (each finite, >= 0) for wavenumber k > 0
  /// [rad/m] (finite); a depth on an interface (LayerStack::locate: within its relative tolerance
  /// of LayerStack::interface_depths) is evaluated at the interface in the medium `side` says.
  /// InvalidArgument on bad input. One solve per call, then O(log n) per depth.
  std::vector<ModeFields> at(double k, std::span<const double> depths,
                             InterfaceSide side = InterfaceSide::below) const;

 private:
  // at() on the global systems of one matrix kind (layer_modes.cpp).
  template <typename System>
  std::vector<ModeFields> solve_at(double k, std::span<const double> depths,
                                   InterfaceSide side) const;
  LayerStack stack_;                       // where each depth lies (LayerStack::locate)
  std::vector<detail::ModeMedium> media_;  // coatings top first, then the substrate
};

}  // namespace coatfft
