#include "model/operator_plan.hpp"

#include <algorithm>
#include <utility>

#include "convolution/operators/operator_memory.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"

namespace coatfft {

std::vector<ReferenceLoad> unknown_load_references(const Grid& grid) {
  return {{AxisymmetricLoad::hertz, std::max(grid.dx(), grid.dy())},
          {AxisymmetricLoad::hertz, 0.5 * std::min(grid.lx(), grid.ly())}};
}

AutomaticChoice choose_automatically(const Grid& grid, const LayerStack& body,
                                     std::vector<ReferenceLoad> loads, AutoRequest request) {
  AutomaticChoice choice;
  choice.applications = request.applications;
  choice.reference_loads = std::move(loads);
  choice.reduction = reduce_body(body, choice.reference_loads, reduction_share * request.tolerance);
  request.tolerance -= choice.reduction->estimated_effect;
  choice.method = choose_method(grid, choice.reduction->body, request);
  return choice;
}

AutomaticChoice choose_automatically(const Grid& grid, const Frf& frf,
                                     std::vector<ReferenceLoad> loads, const AutoRequest& request) {
  AutomaticChoice choice;
  choice.applications = request.applications;
  choice.reference_loads = std::move(loads);
  choice.method = choose_method(grid, frf, request);
  return choice;
}

namespace {

std::vector<ReferenceLoad> loads_of(const Grid& grid, const OperatorRequest& request) {
  return request.loads.empty() ? unknown_load_references(grid) : request.loads;
}

// A periodic "auto" is the exact method of its body. A coating thinner than a hundredth of a cell
// is first reduced as the free boundary's choice reduces it (reduce_body, for the reference loads;
// the closed-form bound decides, with no quadrature): the periodic kernel would otherwise resolve
// the FRF out to k ~ 1/h (1e13 rad/m for a picometre film) and refuse, for an effect far below
// the tolerance.
void plan_periodic(const Grid& grid, const LayerStack& body, const OperatorRequest& request,
                   OperatorPlan& plan) {
  plan.options.method = exact_method(body);
  const double cell = std::min(grid.dx(), grid.dy());
  const bool thin = std::any_of(body.coatings().begin(), body.coatings().end(),
                                [&](const Coating& c) { return c.thickness < 1e-2 * cell; });
  if (!thin) return;
  const BodyReduction r = reduce_body(body, loads_of(grid, request),
                                      reduction_share * request.automatic_request.tolerance);
  if (r.kind == "none") return;
  plan.options.method = exact_method(r.body);
  plan.reduced_body = r.body;
  plan.reduction_note = r.why;
}

// The options "auto" chose, with the request's own g(0) method (an omitted g(0) is the caller's
// choice: a load-controlled contact without the approach).
OperatorOptions chosen_options(const AutomaticChoice& choice, const OperatorRequest& request) {
  OperatorOptions o = choice.method.options;
  o.g0 = request.options.g0;
  return o;
}

// The memory check of `request`, when it asks for one, for the operator of `options`.
void require_request_memory(const Grid& grid, const OperatorOptions& options,
                            const OperatorRequest& request) {
  if (request.other_bytes)
    require_operator_memory(grid, options, *request.other_bytes, request.memory_who);
}

// The default method on the request's boundary takes the least memory any choice of "auto" needs:
// a grid too large for it is refused before the choice spends time on it.
void require_least_memory(const Grid& grid, const OperatorRequest& request) {
  OperatorOptions least;
  least.boundary = request.options.boundary;
  require_request_memory(grid, least, request);
}

}  // namespace

void require_operator_memory(const Grid& grid, const OperatorOptions& options, double other_bytes,
                             std::string_view who) {
  const OperatorMemory m = estimated_memory(grid, options);
  std::string drivers = detail::concat("grid ", grid.nx(), " x ", grid.ny());
  if (m.lattice_nx > 0)
    drivers += detail::concat(" (", m.lattice_nx, " x ", m.lattice_ny, " transform lattice)");
  require_memory({m.bytes + other_bytes, drivers}, std::nullopt, who, "",
                 options.method == Method::frf_spectral ? "use fewer cells or a smaller alpha"
                                                        : "use fewer cells");
}

OperatorPlan plan_operator(const Grid& grid, const LayerStack& body,
                           const OperatorRequest& request) {
  OperatorPlan plan{request.options, std::nullopt, {}, std::nullopt};
  if (request.automatic) require_least_memory(grid, request);
  if (request.automatic && request.options.boundary == Boundary::periodic) {
    plan_periodic(grid, body, request, plan);
  } else if (request.automatic) {
    AutomaticChoice choice =
        choose_automatically(grid, body, loads_of(grid, request), request.automatic_request);
    plan.options = chosen_options(choice, request);
    if (choice.reduction && choice.reduction->kind != "none")
      plan.reduced_body = choice.reduction->body;
    plan.choice = std::move(choice);
  } else if (request.options.boundary == Boundary::free) {
    check_love_body(body, request.options.method);
  }
  check_operator_options(grid, plan.options);
  require_request_memory(grid, plan.options, request);
  return plan;
}

OperatorPlan plan_operator(const Grid& grid, const Frf& frf, const OperatorRequest& request) {
  OperatorPlan plan{request.options, std::nullopt, {}, std::nullopt};
  if (request.automatic) require_least_memory(grid, request);
  if (request.automatic && request.options.boundary == Boundary::periodic) {
    plan.options.method = Method::frf_split;
  } else if (request.automatic) {
    AutomaticChoice choice =
        choose_automatically(grid, frf, loads_of(grid, request), request.automatic_request);
    plan.options = chosen_options(choice, request);
    plan.choice = std::move(choice);
  }
  check_operator_options(grid, plan.options);
  require_request_memory(grid, plan.options, request);
  return plan;
}

BuiltOperator build_operator(const Grid& grid, const LayerStack& body, const OperatorPlan& plan,
                             std::string_view who) {
  BuiltOperator built =
      make_operator(grid, plan.reduced_body ? *plan.reduced_body : body, plan.options);
  refuse_untrustworthy(built.report, who);
  return built;
}

BuiltOperator build_operator(const Grid& grid, const Frf& frf, const OperatorPlan& plan,
                             std::string_view who) {
  BuiltOperator built = make_operator(grid, frf, plan.options);
  refuse_untrustworthy(built.report, who);
  return built;
}

void refuse_untrustworthy(const OperatorReport& report, std::string_view who) {
  const std::optional<double> error = report.predicted_error;
  COATFFT_REQUIRE(!error || *error <= pipeline_refusal_error, who, " = \"",
                  to_string(report.method), "\": predicted error ", *error,
                  " of max |u| on these cells with alpha = ", report.alpha.value_or(0),
                  " (docs/theory.md 4.6): the result would be meaningless; use \"frf-split\" "
                  "(exact on any cells) or square cells and a larger alpha");
}

std::vector<std::string> operator_warnings(const OperatorReport& report) {
  std::vector<std::string> warnings;
  if (report.predicted_error && *report.predicted_error > pipeline_warning_error)
    warnings.push_back(detail::concat(
        "method ", to_string(report.method), ": predicted error ", *report.predicted_error,
        " of max |u| (periodisation of the FRF pipelines at alpha = ", report.alpha.value_or(0),
        ", docs/theory.md 4.6); \"frf-split\" is exact, or raise alpha"));
  return warnings;
}

}  // namespace coatfft
