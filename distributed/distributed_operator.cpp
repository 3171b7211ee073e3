#include "distributed/distributed_operator.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"

namespace coatfft {

Field DistributedOperator::unit_response() {
  Field unit = slab().field();
  if (slab().y0 == 0 && slab().rows > 0) unit(0, 0) = 1.0;
  return apply(unit);
}

namespace {

constexpr const char* kNotShaped =
    "::apply: a rank's pressure is not of its slab's shape (nx, rows), or is its displacement";

bool shaped(const Slab& s, const Field& pressure, const Field& displacement) {
  return pressure.rows() == s.nx && pressure.cols() == s.rows && &pressure != &displacement;
}

}  // namespace

void DistributedOperator::check_pressure(const Field& pressure, const Field& displacement,
                                         std::string_view who) const {
  const bool ok = shaped(slab(), pressure, displacement);
  std::array<double, 2> bad = {ok ? 0.0 : 1.0, ok && !pressure.allFinite() ? 1.0 : 0.0};
  communicator().sum(bad);
  COATFFT_REQUIRE(bad[0] == 0.0, who, kNotShaped);
  COATFFT_REQUIRE(bad[1] == 0.0, who, "::apply: the pressure has a value that is not finite");
}

void DistributedOperator::check_shape(const Field& pressure, const Field& displacement,
                                      std::string_view who) const {
  const double bad = communicator().sum(shaped(slab(), pressure, displacement) ? 0.0 : 1.0);
  COATFFT_REQUIRE(bad == 0.0, who, kNotShaped);
}

void DistributedOperator::check_displacement(const Field& displacement,
                                             std::string_view who) const {
  // A rank without rows has nothing to look at; the others see the same NaN or Inf.
  const bool finite = displacement.size() == 0 || std::isfinite(displacement(0, 0));
  const double bad = communicator().sum(finite ? 0.0 : 1.0);
  COATFFT_REQUIRE(bad == 0.0, who,
                  "::apply: the pressure has a value that is not finite (or too large for the "
                  "displacement to be)");
}

}  // namespace coatfft
