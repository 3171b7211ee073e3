#include "convolution/operators/surface_operator.hpp"

#include "core/detail/huge_pages.hpp"

namespace coatfft {

// The fields are allocated on huge pages before their first touch: at 2048^2 cells a field's
// 4 KiB page faults alone cost about three applications (core/detail/huge_pages.hpp).
Field SurfaceOperator::apply(const Field& pressure) {
  Field u = detail::untouched_array<Field>(pressure.rows(), pressure.cols());
  apply(pressure, u);
  return u;
}

Field SurfaceOperator::unit_response() {
  Field unit = detail::zeroed_array<Field>(grid().nx(), grid().ny());
  unit(0, 0) = 1.0;
  return apply(unit);
}

}  // namespace coatfft
