// Interrupting long calls (core/interrupt.hpp): the hook is asked as often as its interval allows
// and only on its own thread, a hook that says stop makes operator set-up, contact solves,
// stresses and repeated applications throw Interrupted within a bounded number of checks, and
// the objects those calls were given give the same results afterwards.
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <thread>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/detail/timing.hpp"
#include "core/interrupt.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"
#include "stress/stress_operator.hpp"

using namespace coatfft;
using namespace std::chrono_literals;

namespace {

const Material steel(210e9, 0.3);
const Material tin(400e9, 0.25);

// A hook asked at every check (interval 0) that says stop at its `stop_at`-th call, and counts
// its calls and the threads that made them.
struct CountingHook {
  explicit CountingHook(int stop) : stop_at(stop) {}
  int stop_at;
  int calls = 0;
  std::vector<std::thread::id> callers;
  bool operator()() {
    ++calls;
    callers.push_back(std::this_thread::get_id());
    return calls >= stop_at;
  }
};

// Runs `call` under a hook that stops at its `stop_at`-th call: the call must throw Interrupted
// at exactly that call, whatever it was doing.
template <typename Call>
void check_stops_at(int stop_at, Call&& call) {
  CountingHook counter(stop_at);
  {
    const ScopedInterruptHook hook([&counter] { return counter(); }, 0ms);
    CHECK_THROWS_AS(call(), Interrupted);
    CHECK(hook.interrupted());
  }
  CHECK(counter.calls == stop_at);
}

// How many times `call` checks for interrupts when it is not stopped.
template <typename Call>
int checks_of(Call&& call) {
  int calls = 0;
  const ScopedInterruptHook hook([&calls] { return ++calls < 0; }, 0ms);
  call();
  return calls;
}

Grid coated_grid() {
  return Grid(32, 32, 1e-3, 1e-3);
}

LayerStack coated_body() {
  return LayerStack({Coating{tin, 5e-6, Interface::bonded}}, steel);
}

OperatorOptions frf_dcfft_options() {
  OperatorOptions o;
  o.method = Method::frf_dcfft;
  return o;
}

}  // namespace

TEST_CASE("check_interrupt does nothing without a hook", "[interrupt]") {
  CHECK_NOTHROW(check_interrupt());
  CHECK_FALSE(detail::poll_interrupt());
}

TEST_CASE(
    "the hook is asked at every check when its interval is 0, and not again once it said "
    "stop",
    "[interrupt]") {
  CountingHook counter(3);
  const ScopedInterruptHook hook([&counter] { return counter(); }, 0ms);
  CHECK_NOTHROW(check_interrupt());
  CHECK_NOTHROW(check_interrupt());
  CHECK_THROWS_AS(check_interrupt(), Interrupted);
  CHECK_THROWS_AS(check_interrupt(), Interrupted);
  CHECK(counter.calls == 3);
}

TEST_CASE("the hook is asked at most once per interval", "[interrupt]") {
  int calls = 0;
  const ScopedInterruptHook hook([&calls] { return ++calls < 0; }, 1h);
  for (int n = 0; n < 100000; ++n) check_interrupt();
  CHECK(calls == 0);
}

TEST_CASE("hooks nest: the innermost is asked, the outer one is back after it", "[interrupt]") {
  int outer_calls = 0;
  const ScopedInterruptHook outer([&outer_calls] { return ++outer_calls < 0; }, 0ms);
  {
    const ScopedInterruptHook inner([] { return true; }, 0ms);
    CHECK_THROWS_AS(check_interrupt(), Interrupted);
  }
  CHECK_NOTHROW(check_interrupt());
  CHECK(outer_calls == 1);
}

TEST_CASE("parallel_for: the hook is asked on its own thread only, and stops every worker",
          "[interrupt]") {
  CountingHook counter(5);
  std::atomic<long> iterations{0};
  {
    const ScopedInterruptHook hook([&counter] { return counter(); }, 0ms);
    CHECK_THROWS_AS(detail::parallel_for(0, 1000000, 4,
                                         [&](std::ptrdiff_t) {
                                           ++iterations;
                                           std::this_thread::sleep_for(10us);
                                         }),
                    Interrupted);
  }
  CHECK(counter.calls == 5);
  for (const std::thread::id caller : counter.callers) CHECK(caller == std::this_thread::get_id());
  CHECK(iterations.load() < 1000);
}

TEST_CASE("parallel_chunks: the calling thread, once done, asks the hook for a busy worker",
          "[interrupt]") {
  CountingHook counter(3);
  const auto start = std::chrono::steady_clock::now();
  {
    const ScopedInterruptHook hook([&counter] { return counter(); }, 0ms);
    // Worker 0 (the calling thread) has nothing to do; worker 1 checks until it is stopped,
    // or gives up after 20 s (a failure, not a hang).
    CHECK_THROWS_AS(detail::parallel_chunks(0, 2, 2,
                                            [&](std::ptrdiff_t w, std::ptrdiff_t, std::ptrdiff_t) {
                                              if (w == 0) return;
                                              while (std::chrono::steady_clock::now() - start < 20s)
                                                check_interrupt();
                                            }),
                    Interrupted);
  }
  CHECK(counter.calls == 3);
  CHECK(std::chrono::steady_clock::now() - start < 10s);
}

TEST_CASE("an interrupted operator set-up throws, and set-up and operators work afterwards",
          "[interrupt]") {
  const Grid grid = coated_grid();
  const LayerStack body = coated_body();
  const BuiltOperator before = make_operator(grid, body, frf_dcfft_options());
  const Field p = hertz_pressure(grid, 1e9, 0.3e-3, Sampling::cell_average);
  Field u_before;
  before.op->apply(p, u_before);
  // The set-up checks often (every column of the FRF lattice at least): stopped at its 1st,
  // 2nd or 10th check it throws there.
  const int checks = checks_of([&] { make_operator(grid, body, frf_dcfft_options()); });
  CHECK(checks >= 32);
  for (const int stop_at : {1, 2, 10})
    check_stops_at(stop_at, [&] { make_operator(grid, body, frf_dcfft_options()); });
  const BuiltOperator after = make_operator(grid, body, frf_dcfft_options());
  Field u_after, u_again;
  after.op->apply(p, u_after);
  before.op->apply(p, u_again);
  CHECK((u_after == u_before).all());
  CHECK((u_again == u_before).all());
}

TEST_CASE("an interrupted contact solve throws, and the solver and its operator solve again",
          "[interrupt]") {
  const Grid grid(64, 64, 0.4e-3, 0.4e-3);
  const BuiltOperator built = make_operator(grid, LayerStack(steel), OperatorOptions{});
  const Field h = height(grid, Sphere{0.01});
  ContactSolver solver(*built.op, ContactOptions{});
  const ContactResult reference = solver.solve_load(h, 10.0);
  Field u_before;
  built.op->apply(reference.pressure, u_before);
  REQUIRE(reference.converged);
  REQUIRE(reference.iterations > 5);
  // One check per iteration at least.
  CHECK(checks_of([&] { solver.solve_load(h, 10.0); }) >= reference.iterations);
  check_stops_at(5, [&] { solver.solve_load(h, 10.0); });
  const ContactResult again = solver.solve_load(h, 10.0);
  CHECK(again.iterations == reference.iterations);
  CHECK((again.pressure == reference.pressure).all());
  Field u;
  built.op->apply(reference.pressure, u);
  CHECK((u == u_before).all());
}

TEST_CASE("interrupted stresses: set-up and application throw, the operator applies again",
          "[interrupt]") {
  const Grid grid = coated_grid();
  const LayerStack body = coated_body();
  const std::vector<double> depths{5e-5, 1e-4, 2e-4};
  const Field p = hertz_pressure(grid, 1e9, 0.3e-3, Sampling::cell_average);
  check_stops_at(3, [&] { StressOperator(grid, body, depths, StressOperatorOptions{}); });
  StressOperator op(grid, body, depths, StressOperatorOptions{});
  std::vector<PlaneStress> before, after;
  op.apply(p, nullptr, nullptr, before);
  // One check per output (6 per plane) of the application.
  CHECK(checks_of([&] { op.apply(p, nullptr, nullptr, after); }) >= 18);
  check_stops_at(4, [&] { op.apply(p, nullptr, nullptr, after); });
  op.apply(p, nullptr, nullptr, after);
  REQUIRE(after.size() == before.size());
  for (std::size_t d = 0; d < before.size(); ++d)
    for (int c = 0; c < 6; ++c) CHECK((after[d][c] == before[d][c]).all());
}

TEST_CASE("repeated applications stop between two", "[interrupt]") {
  const Grid grid(32, 32, 1e-3, 1e-3);
  const BuiltOperator built = make_operator(grid, LayerStack(steel), OperatorOptions{});
  const Field p = hertz_pressure(grid, 1e9, 0.3e-3, Sampling::cell_average);
  Field u, reference;
  built.op->apply(p, reference);
  check_stops_at(3, [&] { detail::time_applications(*built.op, p, u, 100); });
  detail::time_applications(*built.op, p, u, 2);
  CHECK((u == reference).all());
}
