#include "contact/partial_slip.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "contact/detail/tangential_iteration.hpp"
#include "core/error.hpp"

namespace coatfft {

namespace {

void check_options(const PartialSlipOptions& o) {
  COATFFT_REQUIRE(std::isfinite(o.friction) && o.friction > 0.0,
                  "partial slip: friction = ", o.friction, " must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(o.tolerance) && o.tolerance > 0.0,
                  "partial slip: tolerance must be finite and > 0");
  COATFFT_REQUIRE(o.max_iterations >= 1 && o.max_coupling_solves >= 1,
                  "partial slip: max_iterations and max_coupling_solves must be >= 1");
}

// The relative normal displacement of the tractions alone (the coupling of docs/theory.md 2.9).
Field traction_uz(RelativeSurfaceResponse& response, const Field& qx, const Field& qy,
                  int& applications) {
  std::array<Field, 3> u;
  response.apply(Field::Zero(qx.rows(), qx.cols()), &qx, &qy, u);
  applications += response.applications_per_apply();
  return std::move(u[2]);
}

// Under load control the load must lie below full sliding, mu P.
void check_reach(TangentialControl tangential, double target, double friction,
                 const ContactResult& normal) {
  if (tangential != TangentialControl::load) return;
  COATFFT_REQUIRE(std::abs(target) < friction * normal.load, "partial slip: tangential load ",
                  target, " N reaches full sliding: mu P = ", friction * normal.load,
                  " N (friction ", friction, ", normal load ", normal.load, " N)");
}

// The step's numbers from its converged (or last) tangential solution.
void fill_result(const Grid& grid, const detail::TangentialSolution& t, const Field& bound,
                 PartialSlipResult& r) {
  const double area = grid.dx() * grid.dy();
  r.qx = t.qx;
  r.qy = t.qy;
  r.slip_x = t.sx;
  r.slip_y = t.sy;
  r.stick.resize(bound.rows(), bound.cols());
  const Field size = (t.qx.square() + t.qy.square()).sqrt();
  const Field slip = (t.sx.square() + t.sy.square()).sqrt();
  Eigen::Index stick = 0, contact = 0;
  for (Eigen::Index k = 0; k < bound.size(); ++k) {
    const bool in = bound(k) > 0.0;
    const bool slips = size(k) >= bound(k) * (1.0 - stick_threshold) &&
                       slip(k) > stick_threshold * t.check.slip_scale;
    r.stick(k) = in && !slips ? 1 : 0;
    stick += r.stick(k);
    contact += in ? 1 : 0;
  }
  r.stick_area = static_cast<double>(stick) * area;
  r.slip_area = static_cast<double>(contact - stick) * area;
  r.tangential_load = t.qx.sum() * area;
  r.lateral_load = t.qy.sum() * area;
  r.max_shear = size.maxCoeff();
  r.step_energy = (size * slip).sum() * area;
  r.check = t.check;
}

}  // namespace

PartialSlipState rest_state(RelativeSurfaceResponse& response, const ContactResult& normal) {
  PartialSlipState s;
  s.pressure = normal.pressure;
  s.qx = Field::Zero(normal.pressure.rows(), normal.pressure.cols());
  s.qy = s.qx;
  std::array<Field, 3> u;
  response.apply_in_plane(&s.pressure, nullptr, nullptr, u);
  s.ux = std::move(u[0]);
  s.uy = std::move(u[1]);
  return s;
}

PartialSlipResult solve_partial_slip(ContactSolver& solver, RelativeSurfaceResponse& response,
                                     const Field& height, ContactControl control, double value,
                                     TangentialControl tangential, double target,
                                     const PartialSlipOptions& options,
                                     const PartialSlipState& previous) {
  check_options(options);
  COATFFT_REQUIRE(std::isfinite(target), "partial slip: the tangential ",
                  tangential == TangentialControl::load ? "load" : "shift", " must be finite");
  PartialSlipResult r;
  int applications = 0;
  Field uz = traction_uz(response, previous.qx, previous.qy, applications);
  r.normal = solver.solve(height + uz, control, value);
  r.coupling_solves = 1;
  applications += r.normal.operator_applications;
  bool normal_converged = r.normal.converged, settled = false;
  const double increment =
      tangential == TangentialControl::shift ? target - previous.shift : target;
  Field qx = previous.qx, qy = previous.qy, bound;
  detail::TangentialSolution t;
  // The rounds of the coupling: a tangential solve at the pressure, its normal displacement into
  // the gap, the normal solve again. A round's tangential solve needs an accuracy of a hundredth
  // of the pressure change the round before left (an inexact fixed point: on steel the early
  // rounds' iterations were most of a step's); the last, once the pressure settled, the
  // tolerance itself.
  double accuracy = 1e-3;
  for (int round = 1;; ++round) {
    check_reach(tangential, target, options.friction, r.normal);
    bound = options.friction * r.normal.pressure;
    const detail::TangentialProblem problem{&r.normal.pressure, &bound,     &previous.ux,
                                            &previous.uy,       tangential, increment};
    const double inner = settled ? options.tolerance : std::max(options.tolerance, accuracy);
    const detail::TangentialSettings settings{inner, options.max_iterations, options.on_iteration};
    t = tangential == TangentialControl::load
            // From the last round's shift (0 at first: the previous step's).
            ? detail::solve_tangential_load(response, problem, std::move(qx), std::move(qy),
                                            t.shift_increment, settings)
            : detail::solve_tangential(response, problem, std::move(qx), std::move(qy), settings);
    r.iterations += t.iterations;
    applications += t.applications;
    qx = t.qx;
    qy = t.qy;
    uz = traction_uz(response, qx, qy, applications);
    if ((settled && inner == options.tolerance) || round >= options.max_coupling_solves) break;
    // A coupling below the tolerance of the displacement leaves the pressure as it is.
    if (uz.abs().maxCoeff() <= options.tolerance * r.normal.displacement.abs().maxCoeff()) {
      settled = true;
      continue;
    }
    ContactResult next = solver.solve(height + uz, control, value);
    ++r.coupling_solves;
    applications += next.operator_applications;
    normal_converged = normal_converged && next.converged;
    const double change =
        (next.pressure - r.normal.pressure).abs().maxCoeff() / next.pressure.maxCoeff();
    settled = change <= 10.0 * options.tolerance;
    accuracy = 0.01 * change;
    r.normal = std::move(next);
  }
  r.normal.displacement += uz;
  fill_result(response.grid(), t, bound, r);
  r.tangential_shift = previous.shift + t.shift_increment;
  r.dissipated_energy = previous.dissipated_energy + r.step_energy;
  r.operator_applications = applications;
  r.converged = normal_converged && settled && r.check.holds;
  if (!r.converged)
    r.warning = !normal_converged ? "a normal solve did not converge"
                : !settled        ? "the pressure did not settle under the tractions' coupling"
                                  : "the Coulomb conditions do not hold on every cell";
  r.state = {r.normal.pressure, qx, qy, t.ux, t.uy, r.tangential_shift, r.dissipated_energy};
  return r;
}

std::vector<PartialSlipResult> solve_partial_slip_path(
    ContactSolver& solver, RelativeSurfaceResponse& response, const Field& height,
    ContactControl control, double value, TangentialControl tangential,
    const std::vector<double>& targets, const PartialSlipOptions& options,
    const std::function<void(std::size_t step)>& on_step) {
  check_options(options);
  COATFFT_REQUIRE(!targets.empty(), "partial slip: an empty path");
  PartialSlipState state = rest_state(response, solver.solve(height, control, value));
  std::vector<PartialSlipResult> steps;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    if (on_step) on_step(k);
    steps.push_back(solve_partial_slip(solver, response, height, control, value, tangential,
                                       targets[k], options, state));
    state = steps.back().state;
  }
  return steps;
}

}  // namespace coatfft
