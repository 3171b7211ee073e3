#include "contact/surface_response.hpp"

#include <utility>

#include "core/error.hpp"

namespace coatfft {

namespace {

// The tractions the indenter's surface receives, -q: the fields, and pointers that are null where
// q is (a zero load).
struct IndenterTractions {
  Field x, y;
  const Field *px, *py;
  IndenterTractions(const Field* qx, const Field* qy)
      : x(qx ? Field(-*qx) : Field()),
        y(qy ? Field(-*qy) : Field()),
        px(qx ? &x : nullptr),
        py(qy ? &y : nullptr) {}
};

}  // namespace

RelativeSurfaceResponse::RelativeSurfaceResponse(std::shared_ptr<CerrutiOperator> on_body,
                                                 std::shared_ptr<CerrutiOperator> on_indenter)
    : body_(std::move(on_body)), indenter_(std::move(on_indenter)) {
  COATFFT_REQUIRE(body_ != nullptr, "RelativeSurfaceResponse: no surface response of the body");
  if (!indenter_) return;
  const Grid& b = body_->grid();
  const Grid& i = indenter_->grid();
  COATFFT_REQUIRE(
      b.nx() == i.nx() && b.ny() == i.ny() && b.lx() == i.lx() && b.ly() == i.ly() &&
          body_->periodic() == indenter_->periodic(),
      "RelativeSurfaceResponse: the indenter's response is on another grid or boundary");
}

void RelativeSurfaceResponse::apply(const Field& pressure, const Field* qx, const Field* qy,
                                    std::array<Field, 3>& u) {
  body_->apply(pressure, qx, qy, u);
  if (!indenter_) return;
  const IndenterTractions minus(qx, qy);
  std::array<Field, 3> i;
  indenter_->apply(pressure, minus.px, minus.py, i);
  u[0] -= i[0];
  u[1] -= i[1];
  u[2] += i[2];
}

void RelativeSurfaceResponse::apply_in_plane(const Field* pressure, const Field* qx,
                                             const Field* qy, std::array<Field, 3>& u) {
  body_->apply_in_plane(pressure, qx, qy, u);
  if (!indenter_) return;
  const IndenterTractions minus(qx, qy);
  std::array<Field, 3> i;
  indenter_->apply_in_plane(pressure, minus.px, minus.py, i);
  u[0] -= i[0];
  u[1] -= i[1];
}

}  // namespace coatfft
