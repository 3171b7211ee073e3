// The one operator preparation (model/operator_plan.hpp): a request checked and resolved into the
// options and body make_operator is given, the same for the scene layer and Python.
#include <catch2/catch.hpp>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "frf/coated_frf.hpp"
#include "model/operator_plan.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;
using Catch::Contains;

namespace {

OperatorRequest named(Method method, Boundary boundary = Boundary::free) {
  OperatorRequest request;
  request.automatic = false;
  request.options.method = method;
  request.options.boundary = boundary;
  return request;
}

OperatorRequest automatic(Boundary boundary = Boundary::free) {
  OperatorRequest request;
  request.options.boundary = boundary;
  request.automatic_request.first_in_process = true;
  return request;
}

}  // namespace

TEST_CASE("a named request is checked and planned as it is", "[plan]") {
  const Grid grid(33, 33, 1e-3, 1e-3);
  const LayerStack coated({Coating{tin, 20e-6, Interface::bonded}}, steel);
  const OperatorPlan plan = plan_operator(grid, coated, named(Method::frf_split));
  CHECK(plan.options.method == Method::frf_split);
  CHECK_FALSE(plan.choice);
  CHECK_FALSE(plan.reduced_body);
  // Love's coefficients need a homogeneous body: refused before anything is built.
  CHECK_THROWS_WITH(plan_operator(grid, coated, named(Method::dcfft)), Contains("homogeneous"));
  // Direct summation's cell limit, the one of scenes and Python alike: 65536 cells pass, 65792 not.
  CHECK(plan_operator(Grid(256, 256, 1e-3, 1e-3), LayerStack(steel), named(Method::direct))
            .options.method == Method::direct);
  CHECK_THROWS_WITH(
      plan_operator(Grid(257, 256, 1e-3, 1e-3), LayerStack(steel), named(Method::direct)),
      Contains("direct summation on 257 x 256 cells: it is limited to 65536 cells"));
  CHECK_THROWS_WITH(
      plan_operator(grid, LayerStack(steel), named(Method::frf_dcfft, Boundary::periodic)),
      Contains("computes free (non-periodic) surfaces"));
}

TEST_CASE("auto chooses on a free boundary, keeping the request's g(0)", "[plan]") {
  OperatorRequest request = automatic();
  request.options.g0 = G0Method::omitted;
  const OperatorPlan plan = plan_operator(Grid(33, 33, 3e-3, 3e-3), LayerStack(steel), request);
  REQUIRE(plan.choice);
  // choose_method's own answer for the first operator of a process on 33^2 cells
  // (test_auto_method).
  CHECK(plan.options.method == Method::direct);
  CHECK(plan.options.g0 == G0Method::omitted);
  CHECK(plan.choice->reference_loads.size() == 2);  // the unknown load's two ends
}

TEST_CASE("a distributed auto takes only the methods that run distributed", "[plan]") {
  OperatorRequest request = automatic();
  request.automatic_request.distributed = true;
  const OperatorPlan plan = plan_operator(Grid(33, 33, 3e-3, 3e-3), LayerStack(steel), request);
  REQUIRE(plan.choice);
  CHECK(plan.options.method == Method::dcfft);  // where the serial choice is direct
  for (const MethodCandidate& c : plan.choice->method.candidates)
    if (c.method != Method::dcfft && c.method != Method::frf_split) {
      CHECK_FALSE(c.admissible);
      CHECK(c.note == "does not run distributed");
    }
}

TEST_CASE("a periodic auto takes the exact method, a film far thinner than a cell left out",
          "[plan]") {
  const Grid grid(32, 32, 1e-3, 1e-3);  // cells of 31 um
  const LayerStack film({Coating{tin, 1e-12, Interface::bonded}}, steel);
  const OperatorPlan thin = plan_operator(grid, film, automatic(Boundary::periodic));
  REQUIRE(thin.reduced_body);
  CHECK(thin.reduced_body->is_homogeneous());
  CHECK(thin.options.method == Method::dcfft);
  CHECK_FALSE(thin.reduction_note.empty());
  const LayerStack coated({Coating{tin, 20e-6, Interface::bonded}}, steel);
  const OperatorPlan thick = plan_operator(grid, coated, automatic(Boundary::periodic));
  CHECK_FALSE(thick.reduced_body);
  CHECK(thick.options.method == Method::frf_split);
  // Built for the reduced body: the operator is Love's, as on the bare substrate.
  CHECK(build_operator(grid, film, thin).report.method == Method::dcfft);
}

TEST_CASE("a plan is refused when its operator and the caller's fields exceed the memory",
          "[plan][memory]") {
  const std::optional<double> available = available_memory();
  REQUIRE(available);  // Linux: MemAvailable, the cgroup's limit or ulimit -v
  const Grid grid(64, 64, 1e-3, 1e-3);
  OperatorRequest request = named(Method::dcfft);
  request.memory_who = "make_operator";
  request.other_bytes = 0.0;
  CHECK(plan_operator(grid, LayerStack(steel), request).options.method == Method::dcfft);
  // The caller's fields count beside the operator's own estimate (operator_memory.hpp).
  request.other_bytes = 2.0 * *available;
  CHECK_THROWS_WITH(plan_operator(grid, LayerStack(steel), request),
                    Contains("make_operator needs about") && Contains("driven by grid 64 x 64"));
  // "auto" on a grid no method fits is refused before the choice spends time on it; the FRF
  // form of the body alike.
  const Grid huge(65536, 65536, 1.0, 1.0);  // dcfft: over 100 GiB
  OperatorRequest checked = automatic();
  checked.other_bytes = 0.0;
  CHECK_THROWS_WITH(plan_operator(huge, LayerStack(steel), checked),
                    Contains("operator needs about") && Contains("use fewer cells"));
  const CoatedFrf frf(tin, 20e-6, steel, Interface::bonded);
  checked = automatic(Boundary::periodic);
  checked.other_bytes = 0.0;
  CHECK_THROWS_WITH(plan_operator(huge, frf, checked), Contains("operator needs about"));
  // Unset, the caller checks memory itself against its own limit (the scene layer: --max-memory,
  // a rank's share under mpirun): the plan does not.
  CHECK(plan_operator(huge, LayerStack(steel), named(Method::dcfft)).options.method ==
        Method::dcfft);
}
