#include "contact/sliding_contact.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "contact/surface_response.hpp"
#include "core/error.hpp"

namespace coatfft {

TangentialCoupling traction_coupling(std::shared_ptr<CerrutiOperator> on_body,
                                     std::shared_ptr<CerrutiOperator> on_indenter) {
  auto response =
      std::make_shared<RelativeSurfaceResponse>(std::move(on_body), std::move(on_indenter));
  return [response](const Field& qx) {
    std::array<Field, 3> u;
    response->apply(Field::Zero(qx.rows(), qx.cols()), &qx, nullptr, u);
    return std::move(u[2]);
  };
}

namespace {

// The x coordinate of the centroid of p [m] (p >= 0, not all zero).
double centroid_x(const Grid& g, const Field& p) {
  double moment = 0.0;
  for (std::ptrdiff_t i = 0; i < g.nx(); ++i) moment += g.x(i) * p.row(i).sum();
  return moment / p.sum();
}

}  // namespace

ContactResult solve_sliding(ContactSolver& solver, const TangentialCoupling& coupling,
                            const Field& height, ContactControl control, double value,
                            const SlidingOptions& options, SlidingReport* report) {
  COATFFT_REQUIRE(std::isfinite(options.friction) && options.friction >= 0,
                  "sliding contact: friction = ", options.friction, " must be finite and >= 0");
  COATFFT_REQUIRE(std::isfinite(options.tolerance) && options.tolerance > 0,
                  "sliding contact: tolerance must be finite and > 0");
  COATFFT_REQUIRE(options.max_iterations >= 1, "sliding contact: max_iterations must be >= 1");
  SlidingReport r;
  if (options.on_solve) options.on_solve(1);
  ContactResult result = solver.solve(height, control, value);
  r.solves = 1;
  int applications = result.operator_applications;
  bool all_converged = result.converged;
  Field shift;
  const double p_max = result.pressure.maxCoeff();
  if (options.friction > 0.0 && p_max > 0.0) {
    const Field frictionless = result.pressure;
    while (r.solves < options.max_iterations) {
      shift = coupling(options.friction * result.pressure);
      if (options.on_solve) options.on_solve(r.solves + 1);
      ContactResult next = solver.solve(height + shift, control, value);
      ++r.solves;
      applications += next.operator_applications;
      all_converged = all_converged && next.converged;
      r.pressure_change = (next.pressure - result.pressure).abs().maxCoeff() / p_max;
      result = std::move(next);
      if (r.pressure_change <= options.tolerance) break;
    }
    r.pressure_shift = (result.pressure - frictionless).abs().maxCoeff() / p_max;
    r.centroid_shift =
        centroid_x(solver.grid(), result.pressure) - centroid_x(solver.grid(), frictionless);
    // The displacement of the tractions of the final pressure (the gap used the previous one's,
    // within the tolerance).
    result.displacement += coupling(options.friction * result.pressure);
  }
  result.operator_applications = applications;  // the cost of all the solves
  r.converged =
      all_converged && (options.friction == 0.0 || r.pressure_change <= options.tolerance);
  if (!r.converged && result.converged) {  // the normal solves converged, the coupling did not
    result.converged = false;
    result.status = ContactStatus::coupling_limit;
    result.warning = detail::concat("the friction coupling did not converge in ", r.solves,
                                    " normal solves (pressure change ", r.pressure_change,
                                    ", tolerance ", options.tolerance, ")");
  }
  if (report) *report = r;
  return result;
}

}  // namespace coatfft
