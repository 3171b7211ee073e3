#include "contact/plastic_report.hpp"

#include "core/error.hpp"

namespace coatfft {

PlasticReport plastic_report(const ContactResult& result, double hardness, const Grid& grid) {
  COATFFT_REQUIRE(
      result.plastic_depth.size() == result.pressure.size() && result.pressure.size() > 0,
      "plastic_report: the contact was solved without a hardness");
  const double cell_area = grid.dx() * grid.dy();
  PlasticReport r;
  // The solver leaves the cells at the cap at exactly the hardness (clipped, never scaled).
  r.plastic_area = static_cast<double>((result.pressure >= hardness).count()) * cell_area;
  r.plastic_area_fraction = result.contact_area > 0 ? r.plastic_area / result.contact_area : 0.0;
  r.max_plastic_depth = result.plastic_depth.maxCoeff();
  r.plastic_volume = result.plastic_depth.sum() * cell_area;
  return r;
}

Field residual_gap(const Field& height, const Field& plastic_depth) {
  COATFFT_REQUIRE(height.rows() == plastic_depth.rows() && height.cols() == plastic_depth.cols(),
                  "residual_gap: the heights and the plastic depth differ in shape");
  const Field surface = height + plastic_depth;
  return surface - surface.minCoeff();
}

}  // namespace coatfft
