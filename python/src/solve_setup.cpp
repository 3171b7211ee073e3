#include "solve_setup.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bodies.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"

namespace coatfft::python {

ContactOptions contact_options(const Operator& op, bool approach_control, double tolerance,
                               int max_iterations, bool preconditioned, const char* what) {
  ContactOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  options.preconditioned = preconditioned;
  options.threads = op.threads();
  // The approach is part of the result, unless the operator was built without g(0) (a named
  // pipeline with g0 = "omitted"), which leaves the displacement's level unknown. Under approach
  // control that level is what the approach is measured against: the solve would converge to a
  // wrong load, so it is refused.
  options.compute_approach = op.has_g0();
  COATFFT_REQUIRE(options.compute_approach || !approach_control, what,
                  ": approach control needs the displacement's level, but the "
                  "operator was built with g0 = \"omitted\"; build it with g0 = \"regularized\" "
                  "or \"quadrature\", or give a load");
  return options;
}

// The normal displacement of one body and the tractions' of another would be added into one
// gap, a result of no body. The two FRFs
// are compared on the wavenumbers of the operator's grid (its longest period to its Nyquist),
// where both are evaluated by the same code for the same body, and to 1e-6 where one is a table.
void require_operator_body(const Operator& op, const LayerStack& body, const char* what) {
  const Grid& g = op.grid();
  const double k_min = 2.0 * std::numbers::pi / std::max(g.lx(), g.ly());
  const double k_max = std::numbers::pi / std::min(g.dx(), g.dy());
  const std::shared_ptr<const Frf> given = Body{body, nullptr}.response();
  constexpr int samples = 16;
  for (int n = 0; n < samples; ++n) {
    const double k = k_min * std::pow(k_max / k_min, n / (samples - 1.0));
    const double own = op.body_response()(k), other = (*given)(k);
    COATFFT_REQUIRE(std::abs(own - other) <= 1e-6 * std::abs(own), what,
                    ": body is not the body the operator was made for (their FRFs differ by ",
                    std::abs(own - other) / std::abs(own), " at k = ", k,
                    " 1/m): pass the operator's body");
  }
}

std::shared_ptr<CerrutiOperator> surface_response(Operator& op, const LayerStack& body,
                                                  int threads) {
  TangentialOptions tangential;
  tangential.threads = threads;
  tangential.boundary = op.op().periodic() ? Boundary::periodic : Boundary::free;
  return make_tangential_operator(op.grid(), body, tangential).op;
}

}  // namespace coatfft::python
