#pragma once
// The surface response of any layer stack to a pressure and to tangential tractions, as four
// radial functions of the wavenumber (docs/theory.md 2.9): u_z under p (the Frf H_zz), the
// in-plane compliances S = (H_LL + H_TT)/2 and D = (H_LL - H_TT)/2 (L along the wavevector, T
// across it) and the normal-tangential coupling C. With theta the direction of the wavevector and
// the forward transform exp(-i k.x),
//   u_x = (S + D cos 2theta) q_x + D sin 2theta q_y + i C cos theta p,
//   u_y = D sin 2theta q_x + (S - D cos 2theta) q_y + i C sin theta p,
//   u_z = -i C cos theta q_x - i C sin theta q_y + H_zz p.
// They are the z = 0 mode coefficients of LayerModes: H_zz = uz_p, S and D from uL_q and uT_t,
// C = uz_q = uL_p (Betti's reciprocity).
#include <memory>

#include "../layers/layer_stack.hpp"
#include "frf.hpp"
#include "layer_modes.hpp"

namespace coatfft {

/// The four surface FRFs at one wavenumber [m/Pa].
struct TractionFrfs {
  double zz = 0.0;  ///< u_z per unit p
  double s = 0.0;   ///< (H_LL + H_TT)/2
  double d = 0.0;   ///< (H_LL - H_TT)/2
  double c = 0.0;   ///< coupling: u_z = -i C cos(theta) per unit q_x
};

class TractionResponse {
 public:
  /// Any stack; the limit at k -> 0 of the in-plane terms is finite only when every interface is
  /// bonded (a coating over a frictionless interface slides: S and D grow like 1/k^2).
  explicit TractionResponse(const LayerStack& stack);

  /// The FRFs at k > 0 [rad/m] (finite). InvalidArgument otherwise.
  TractionFrfs operator()(double k) const;
  /// k times the FRFs as k -> 0: the substrate's half-space (bonded stacks) [1/Pa].
  const TractionFrfs& at_zero() const { return at_zero_; }
  /// k times the FRFs as k -> infinity: the top medium's half-space [1/Pa].
  const TractionFrfs& at_infinity() const { return at_infinity_; }
  /// Whether every interface is bonded (at_zero is then the limit of the stack).
  bool bonded() const { return bonded_; }

 private:
  LayerModes modes_;
  TractionFrfs at_zero_, at_infinity_;
  bool bonded_;
};

/// k times the surface FRFs of the homogeneous half-space of `material` (independent of k):
/// H_zz = S + D = (1 - nu)/mu, S = (2 - nu)/(2 mu), D = -nu/(2 mu), C = (1 - 2 nu)/(2 mu).
TractionFrfs half_space_traction_frfs(const Material& material);

/// S(k) as an Frf (positive, with S's limits as c0 and c_inf): its radial kernel is what frf-split
/// builds for any Frf (convolution/kernels/split_frf_kernel.hpp).
std::unique_ptr<Frf> in_plane_frf(const LayerStack& stack);

}  // namespace coatfft
