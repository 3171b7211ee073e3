// The contact iteration's element-wise passes on two threads (ContactOptions::threads, from
// 512^2 cells) against one thread. A 512^2 solve twice: labelled slow (run by .ci/run).
#include <catch2/catch.hpp>

#include "contact/contact_solver.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/norms.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "tests/rough_test_gap.hpp"

using namespace coatfft;

namespace {
const Material kSteel(210e9, 0.3);
}  // namespace

TEST_CASE("Element-wise passes on two threads give the one-thread contact", "[contact][threads]") {
  // 512^2 cells: the passes run on ContactOptions::threads from there. Chunked sums change only
  // the rounding, so the two solves meet at the same solution to the solver tier.
  const Grid grid(512, 512, 1e-3, 1e-3);
  const Field h = test::rough_test_gap(grid, 16, 3);
  PeriodicOperator op(grid, periodic_influence_kernel(grid, *make_frf(LayerStack(kSteel))),
                      Method::dcfft);
  const double load = 0.05 * kSteel.plane_strain_modulus() * 0.05 * 1e-6;
  ContactOptions two;
  two.threads = 2;
  const ContactResult one_thread = ContactSolver(op).solve_load(h, load);
  const ContactResult two_threads = ContactSolver(op, two).solve_load(h, load);
  INFO("iterations " << one_thread.iterations << ", " << two_threads.iterations);
  REQUIRE(one_thread.converged);
  REQUIRE(two_threads.converged);
  CHECK(rel_linf(two_threads.pressure, one_thread.pressure) <= 1e-8);
  CHECK((two_threads.pressure > 0).count() == (one_thread.pressure > 0).count());
}
