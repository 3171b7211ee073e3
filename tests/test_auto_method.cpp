// The automatic method choice (model/auto_method.hpp): what it chooses, and that the error it
// achieves is within the tolerance, against the exact convolution of the same cell-wise load
// (Love's DC-FFT on a homogeneous body; frf-split at a kernel tolerance of 1e-13 on a coated one,
// whose own error is below 1e-12 of max |u|: bench/results/auto_calibration.csv and
// tests/test_split_kernel.cpp against the Hankel reference).
#include <catch2/catch.hpp>
#include <cmath>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "model/auto_method.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

LayerStack coated(double E, double h) {
  return LayerStack({Coating{Material(E, 0.3), h, Interface::bonded}}, steel);
}

double achieved_error(const Grid& grid, const LayerStack& body, const OperatorOptions& chosen) {
  const Field p = hertz_pressure(grid, 1e9, grid.lx() / 3, Sampling::cell_average);
  OperatorOptions ref;
  ref.method = body.is_homogeneous() ? Method::dcfft : Method::frf_split;
  ref.split.tolerance = 1e-13;
  Field u, u_ref;
  make_operator(grid, body, chosen).op->apply(p, u);
  make_operator(grid, body, ref).op->apply(p, u_ref);
  return (u - u_ref).abs().maxCoeff() / u_ref.abs().maxCoeff();
}

}  // namespace

TEST_CASE("auto picks Love's DC-FFT for a homogeneous body, direct summation on small grids",
          "[auto]") {
  AutoRequest r;
  const MethodChoice big = choose_method(Grid(128, 128, 3e-3, 3e-3), LayerStack(steel), r);
  CHECK(big.options.method == Method::dcfft);
  CHECK(big.chosen.predicted_error <= 1e-12);
  CHECK(!big.why.empty());
  REQUIRE(big.candidates.size() == 5);
  // The first operator of a process (a command-line run) pays FFTW's start, ~8 ms: on 33^2 cells
  // the 1.2e6 products of direct summation (~0.6 ms) are cheaper; on 128^2 (2.7e8) they are not.
  AutoRequest fresh;
  fresh.first_in_process = true;
  CHECK(choose_method(Grid(33, 33, 3e-3, 3e-3), LayerStack(steel), fresh).options.method ==
        Method::direct);
  CHECK(choose_method(Grid(128, 128, 3e-3, 3e-3), LayerStack(steel), fresh).options.method ==
        Method::dcfft);
}

TEST_CASE("auto's frf-split meets the tolerance on coated bodies", "[auto]") {
  const Grid grid(64, 64, 3e-3, 3e-3);
  for (const double E : {21e9, 2100e9})
    for (const double h : {1e-4, 1e-3})
      for (const double tolerance : {1e-2, 1e-3, 1e-4, 1e-6}) {
        const LayerStack body = coated(E, h);
        AutoRequest r;
        r.tolerance = tolerance;
        const MethodChoice c = choose_method(grid, body, r);
        INFO("E " << E << " h " << h << " tolerance " << tolerance << ": " << c.why);
        CHECK(c.options.method == Method::frf_split);
        CHECK(c.chosen.predicted_error <= tolerance);
        const double achieved = achieved_error(grid, body, c.options);
        CHECK(achieved <= c.chosen.predicted_error);
      }
}

TEST_CASE("Love's methods are not admissible for a coated body; bad requests are refused",
          "[auto]") {
  const Grid grid(32, 32, 3e-3, 3e-3);
  OperatorOptions dcfft;
  dcfft.method = Method::dcfft;
  const MethodCandidate c = predict_method(grid, coated(21e9, 1e-4), dcfft, 1.0);
  CHECK_FALSE(c.admissible);
  CHECK(std::isinf(c.predicted_error));
  AutoRequest bad;
  bad.tolerance = 0.0;
  CHECK_THROWS_AS(choose_method(grid, LayerStack(steel), bad), InvalidArgument);
  bad.tolerance = std::nan("");
  CHECK_THROWS_AS(choose_method(grid, LayerStack(steel), bad), InvalidArgument);
  bad = AutoRequest{};
  bad.applications = 0.5;
  CHECK_THROWS_AS(choose_method(grid, LayerStack(steel), bad), InvalidArgument);
}

TEST_CASE("many applications weigh the application, one application the setup", "[auto]") {
  const Grid grid(128, 128, 3e-3, 3e-3);
  AutoRequest once, many;
  many.applications = 100;
  const MethodChoice a = choose_method(grid, coated(21e9, 1e-3), once);
  const MethodChoice b = choose_method(grid, coated(21e9, 1e-3), many);
  CHECK(b.chosen.total_seconds - a.chosen.total_seconds ==
        Approx(99 * a.chosen.apply_seconds).epsilon(1e-9));
}

TEST_CASE("auto's lattice alpha makes alpha n a fast FFT length on square grids", "[auto]") {
  CHECK(lattice_alpha(Grid(128, 128, 1, 1)) == 2.0);
  const double alpha = lattice_alpha(Grid(127, 127, 1, 1));
  CHECK(alpha * 127 == Approx(256).epsilon(1e-14));
  CHECK(lattice_alpha(Grid(127, 64, 1, 1)) == 2.0);  // no one alpha rounds both axes
  // The operator accepts it: alpha n is whole.
  OperatorOptions o;
  o.method = Method::frf_spectral;
  o.alpha = alpha;
  CHECK_NOTHROW(check_operator_options(Grid(127, 127, 1, 1), o));
}
