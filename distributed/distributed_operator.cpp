#include "distributed/distributed_operator.hpp"

#include <array>

#include "core/error.hpp"

namespace coatfft {

Field DistributedOperator::unit_response() {
  Field unit = slab().field();
  if (slab().y0 == 0 && slab().rows > 0) unit(0, 0) = 1.0;
  return apply(unit);
}

void DistributedOperator::check_pressure(const Field& pressure, const Field& displacement,
                                         std::string_view who) const {
  const Slab& s = slab();
  const bool shaped =
      pressure.rows() == s.nx && pressure.cols() == s.rows && &pressure != &displacement;
  std::array<double, 2> bad = {shaped ? 0.0 : 1.0, shaped && !pressure.allFinite() ? 1.0 : 0.0};
  communicator().sum(bad);
  COATFFT_REQUIRE(bad[0] == 0.0, who,
                  "::apply: a rank's pressure is not of its slab's shape (nx, rows), or is its "
                  "displacement");
  COATFFT_REQUIRE(bad[1] == 0.0, who, "::apply: the pressure has a value that is not finite");
}

}  // namespace coatfft
