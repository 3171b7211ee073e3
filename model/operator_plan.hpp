#pragma once
// One operator preparation, as FINUFFT's plan: an operator request (a named method, or "auto" with
// a tolerance; its options; the boundary) for a grid and a body is checked and resolved into a
// plan (the options make_operator is given, the body it builds for: reduced by "auto"
// (model/body_reduction.hpp), and the choice made, model/auto_method.hpp); build_operator then
// builds the plan's operator and refuses one whose predicted error makes it meaningless. The scene
// layer (scene/automatic_method.hpp, scene/operator_from_scene.hpp) and the Python module's
// make_operator prepare operators here, and nowhere else.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../convolution/operators/make_operator.hpp"
#include "../core/grid.hpp"
#include "../frf/frf.hpp"
#include "../layers/layer_stack.hpp"
#include "auto_method.hpp"
#include "body_reduction.hpp"

namespace coatfft {

/// Share of the tolerance a reduced body may use; the operator gets the rest. The operator's own
/// predicted error is at most a tenth of the tolerance (frf-split's kernel tolerance is set so;
/// Love's methods are exact), so a reduction may use nine tenths.
inline constexpr double reduction_share = 0.9;

/// Thresholds on the predicted error of the FRF pipelines frf-spectral and frf-dcfft
/// (OperatorReport::predicted_error, docs/theory.md 4.6), relative to max |u|: above the first a
/// computation warns, above the second its result cannot be trusted at all and it is refused.
inline constexpr double pipeline_warning_error = 1e-2;
inline constexpr double pipeline_refusal_error = 1.0;

/// What "auto" chose on a free boundary: the body (reduced for the reference loads) and the method.
struct AutomaticChoice {
  std::vector<ReferenceLoad> reference_loads;  ///< what the reduction's effect was bounded for
  std::optional<BodyReduction> reduction;      ///< none for a body given by its FRF
  MethodChoice method;
  double applications = 1.0;
};

/// The reference loads of a load whose shape is not known (a file, a cylinder, a height map, or
/// none yet): a Hertz load one cell wide and one half the domain wide, the two ends of the range
/// of sizes the grid can hold.
std::vector<ReferenceLoad> unknown_load_references(const Grid& grid);

/// The automatic choice for a layered body on `grid`: the reduced body (reduction_share of the
/// tolerance, for `loads`), then the method for the rest of request.tolerance.
AutomaticChoice choose_automatically(const Grid& grid, const LayerStack& body,
                                     std::vector<ReferenceLoad> loads, AutoRequest request);
/// The same for a body given by its FRF alone, which is never reduced.
AutomaticChoice choose_automatically(const Grid& grid, const Frf& frf,
                                     std::vector<ReferenceLoad> loads, const AutoRequest& request);

/// An operator asked for: a named method and its options, or "auto".
struct OperatorRequest {
  /// "auto": on a free boundary the method (and the body) chosen for `automatic.tolerance`; on a
  /// periodic one the body's exact method (exact_method), a coating thinner than a hundredth of a
  /// cell left out where its effect is within the tolerance.
  bool automatic = true;
  /// A named method's options, and the boundary (options.boundary); for "auto" its g(0) method
  /// is kept (an omitted g(0) is the caller's choice) and its threads cap the choice's.
  OperatorOptions options;
  /// "auto"'s tolerance, applications, planning and threads (AutoRequest).
  AutoRequest automatic_request;
  /// "auto"'s reference loads; empty: unknown_load_references(grid).
  std::vector<ReferenceLoad> loads;
  /// The memory check before any work (require_operator_memory): the bytes the caller holds
  /// beside the operator (its own fields), and the name a refusal starts with. Unset: the caller
  /// checks its memory itself, against its own limit (the scene layer: the whole run's estimate
  /// against --max-memory, or a rank's share of it under mpirun).
  std::optional<double> other_bytes;
  std::string memory_who = "operator";
};

/// A request resolved: what make_operator is given.
struct OperatorPlan {
  OperatorOptions options;
  /// The body "auto" reduced, when it reduced it (build for it instead of the body given).
  std::optional<LayerStack> reduced_body;
  std::string reduction_note;             ///< why, when reduced on a periodic boundary
  std::optional<AutomaticChoice> choice;  ///< "auto" on a free boundary
};

/// Refuses (InvalidArgument starting with `who`, naming the grid and any transform lattice) an
/// operator of `options` on `grid` whose estimated memory (operator_memory.hpp), with
/// `other_bytes` beside it, exceeds the memory available (core/memory.hpp).
void require_operator_memory(const Grid& grid, const OperatorOptions& options, double other_bytes,
                             std::string_view who);

/// Checks `request` for `body` on `grid` (check_operator_options, Love's methods on a homogeneous
/// body only, direct summation's cell limit), resolves "auto" and, when the request asks
/// (other_bytes), checks the memory of the operator planned (require_operator_memory; for "auto"
/// first that of the least any choice needs, before the choice spends time on a grid too large).
/// InvalidArgument for a bad request, when no method meets the tolerance, or when the operator
/// does not fit.
OperatorPlan plan_operator(const Grid& grid, const LayerStack& body,
                           const OperatorRequest& request);
/// The same for a body given by its FRF alone (periodic "auto" takes frf-split; never reduced).
OperatorPlan plan_operator(const Grid& grid, const Frf& frf, const OperatorRequest& request);

/// make_operator of the plan (for its reduced body, if any, else `body`), refused when the
/// operator's predicted error exceeds pipeline_refusal_error (refuse_untrustworthy, naming `who`).
BuiltOperator build_operator(const Grid& grid, const LayerStack& body, const OperatorPlan& plan,
                             std::string_view who = "method");
/// The same for a body given by its FRF alone.
BuiltOperator build_operator(const Grid& grid, const Frf& frf, const OperatorPlan& plan,
                             std::string_view who = "method");

/// Throws InvalidArgument when the report's predicted error exceeds pipeline_refusal_error; the
/// message starts with `who` and the method's name (`[method] name = "frf-spectral"`).
void refuse_untrustworthy(const OperatorReport& report, std::string_view who);

/// Warnings about what was built: an FRF pipeline whose predicted error exceeds
/// pipeline_warning_error.
std::vector<std::string> operator_warnings(const OperatorReport& report);

}  // namespace coatfft
