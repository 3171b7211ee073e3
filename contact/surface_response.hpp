#pragma once
// The displacement of the body's surface relative to the indenter's under the contact tractions:
// the pressure p and the tangential tractions q that the body's surface receives, the indenter's
// receiving p and -q. Seen from the indenter (its z axis into it, the other way), its surface
// moves by (i_x, i_y, -i_z) with i = (its response to p and -q), so the relative displacement is
//   (b_x - i_x, b_y - i_y, b_z + i_z),   b = (the body's response to p and q):
// the in-plane compliances under q add ((2 - nu)/G summed, Johnson 1985 eq. 7.43), the normal
// ones under p add (the composite modulus), and the couplings subtract (beta of Johnson 1985,
// section 5.4: none between identical bodies). A rigid indenter contributes nothing.
#include <array>
#include <memory>

#include "../convolution/operators/cerruti_operator.hpp"

namespace coatfft {

class RelativeSurfaceResponse {
 public:
  /// `on_body`: the body's 3 x 3 surface response; `on_indenter`: an elastic indenter's on the
  /// same grid and boundary (null: rigid). InvalidArgument when the body's is missing or the two
  /// differ in grid or boundary.
  explicit RelativeSurfaceResponse(std::shared_ptr<CerrutiOperator> on_body,
                                   std::shared_ptr<CerrutiOperator> on_indenter = nullptr);

  const Grid& grid() const { return body_->grid(); }
  bool periodic() const { return body_->periodic(); }
  /// The number of 3 x 3 operator applications one apply makes (1 or 2).
  int applications_per_apply() const { return indenter_ ? 2 : 1; }

  /// u = (u_x, u_y, u_z) [m] of the body's surface relative to the indenter's (u_z: their
  /// approach) under `pressure` and the tractions `qx`, `qy` (null: zero) the body receives [Pa].
  void apply(const Field& pressure, const Field* qx, const Field* qy, std::array<Field, 3>& u);
  /// u_x and u_y alone (u[2] left as it was), `pressure` null for zero: two thirds of apply's
  /// transforms, or less (CerrutiOperator::apply_in_plane).
  void apply_in_plane(const Field* pressure, const Field* qx, const Field* qy,
                      std::array<Field, 3>& u);

 private:
  std::shared_ptr<CerrutiOperator> body_, indenter_;
};

}  // namespace coatfft
