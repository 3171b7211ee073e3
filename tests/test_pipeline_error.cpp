// The error model of the FRF pipelines (convolution/operators/pipeline_error.hpp,
// docs/theory.md 4.6): the prediction is the error measured on the grid itself when the grid is its
// own proxy, close to it on larger grids, flags the anisotropic cells of a thin domain, falls with
// alpha, and stays cheap on extreme grids.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>

#include "convolution/operators/make_operator.hpp"
#include "convolution/operators/pipeline_error.hpp"
#include "core/error.hpp"
#include "frf/half_space_frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/catalog.hpp"

using namespace coatfft;

namespace {

const Material steel = material_by_name("steel");
const LayerStack bare(steel);
// TiN 2 um on steel: the coating of the thin-domain case below.
const LayerStack tin({Coating{material_by_name("titanium_nitride"), 2e-6, Interface::bonded}},
                     steel);
// A stiff coating as thick as the reference load's radius (L = 3 mm, a = 1 mm): the regime where
// the coating raises the error most (docs/validation/pipeline_error.md, section 3).
const LayerStack stiff({Coating{Material(2100e9, 0.3), 1e-3, Interface::bonded}}, steel);

// The error of `method` on `grid` measured directly, through make_operator with its defaults,
// against Love's DC-FFT (a bare body) or frf-split (a coated one) under the reference load.
double measured_error(const Grid& grid, const LayerStack& body, Method method, double alpha) {
  OperatorOptions exact;
  exact.method = body.is_homogeneous() ? Method::dcfft : Method::frf_split;
  OperatorOptions pipeline;
  pipeline.method = method;
  pipeline.alpha = alpha;
  const Field p = pipeline_error_reference_load(grid);
  const Field reference = make_operator(grid, body, exact).op->apply(p);
  const Field u = make_operator(grid, body, pipeline).op->apply(p);
  return (u - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

constexpr Method pipelines[] = {Method::frf_spectral, Method::frf_dcfft};

}  // namespace

TEST_CASE("a grid that is its own proxy is predicted exactly", "[pipeline_error]") {
  struct Case {
    Grid grid;
    double alpha;
  };
  // Square cells; rectangular cells of a rectangular domain at alpha = 3; the thin domain of
  // 4 mm x 40 um on 64^2 cells (dx/dy = 100).
  const Case cases[] = {{Grid(64, 64, 3e-3, 3e-3), 2.0},
                        {Grid(48, 32, 3e-3, 4e-3), 3.0},
                        {Grid(64, 64, 4e-3, 40e-6), 2.0}};
  for (const Case& c : cases) {
    const PipelineErrorProxy proxy = pipeline_error_proxy(c.grid, c.alpha);
    CHECK(proxy.grid == c.grid);
    CHECK(proxy.alpha == c.alpha);
    for (const Method method : pipelines) {
      INFO(to_string(method) << " on " << c.grid.nx() << " x " << c.grid.ny());
      const double predicted = predicted_pipeline_error(c.grid, method, c.alpha);
      CHECK(predicted == Approx(measured_error(c.grid, bare, method, c.alpha)).epsilon(1e-10));
    }
  }
}

TEST_CASE("on a larger grid the 64-cell proxy is within its convergence in N", "[pipeline_error]") {
  // The pipelines' error is a periodisation error, nearly independent of N: 64 cells across the
  // shorter side are converged to ~1 % at alpha = 2 (docs/validation/pipeline_error.md,
  // section 2), so 2 % is the bound. The thin domain at 256^2 keeps its 256 cells along x
  // (cells no smaller than ly/64), where the reference load spans under a cell.
  const Grid square(256, 256, 3e-3, 3e-3);
  const Grid thin(256, 256, 4e-3, 40e-6);
  CHECK(pipeline_error_proxy(square, 2.0).grid == Grid(64, 64, 3e-3, 3e-3));
  CHECK(pipeline_error_proxy(thin, 2.0).grid == Grid(256, 64, 4e-3, 40e-6));
  for (const Grid& grid : {square, thin})
    for (const Method method : pipelines) {
      INFO(to_string(method) << ", lx / ly = " << grid.lx() / grid.ly());
      const double predicted = predicted_pipeline_error(grid, method, 2.0);
      CHECK(predicted == Approx(measured_error(grid, bare, method, 2.0)).epsilon(0.02));
    }
}

TEST_CASE("the model flags cells of aspect ratio 100 and gives ~2 % on square cells",
          "[pipeline_error]") {
  const Grid thin(64, 64, 4e-3, 40e-6);
  const Grid square(128, 128, 3e-3, 3e-3);
  const auto tin_frf = make_frf(tin);
  for (const Method method : pipelines) {
    INFO(to_string(method));
    // Measured: +120 % at the centre and negative displacements
    // (docs/validation/pipeline_error.md).
    CHECK(predicted_pipeline_error(thin, method, 2.0) > 1.0);
    CHECK(predicted_pipeline_error(thin, *tin_frf, method, 2.0) > 1.0);
    const double e2 = predicted_pipeline_error(square, method, 2.0);
    CHECK(e2 >= 1e-2);
    CHECK(e2 <= 4e-2);
    // A periodisation error: it falls with alpha, about as 1/alpha.
    double previous = e2;
    for (const double alpha : {3.0, 4.0, 8.0}) {
      const double e = predicted_pipeline_error(square, method, alpha);
      CHECK(e < previous);
      CHECK(e * alpha == Approx(2.0 * e2).epsilon(0.2));
      previous = e;
    }
  }
}

TEST_CASE("the FRF model measures a stiff coating with the body's own FRF", "[pipeline_error]") {
  const Grid grid(64, 64, 3e-3, 3e-3);
  const auto frf = make_frf(stiff);
  for (const Method method : pipelines) {
    INFO(to_string(method));
    const double predicted = predicted_pipeline_error(grid, *frf, method, 2.0);
    // The split kernel of the model runs at a relative tolerance of 1e-6, make_operator's at
    // 1e-11: equal to well within 1e-4 of the error.
    CHECK(predicted == Approx(measured_error(grid, stiff, method, 2.0)).epsilon(1e-4));
    // The homogeneous model misses the stiff coating by a factor ~2.7 (measured 6.7e-2 vs 2.5e-2).
    CHECK(predicted > 2.0 * predicted_pipeline_error(grid, method, 2.0));
    // A half-space FRF is the homogeneous model, whatever its modulus.
    const HalfSpaceFrf half_space(steel);
    CHECK(predicted_pipeline_error(grid, half_space, method, 2.0) ==
          predicted_pipeline_error(grid, method, 2.0));
  }
}

TEST_CASE("make_operator reports the prediction of the FRF pipelines only", "[pipeline_error]") {
  const Grid grid(32, 32, 3e-3, 3e-3);
  const auto frf = make_frf(tin);
  for (const Method method : all_methods) {
    OperatorOptions options;
    options.method = method;
    options.alpha = 4.0;
    const BuiltOperator built =
        make_operator(grid, uses_love_coefficients(method) ? bare : tin, options);
    INFO(to_string(method));
    REQUIRE(built.report.predicted_error.has_value() == samples_frf_lattice(method));
    if (!samples_frf_lattice(method)) continue;
    CHECK(*built.report.predicted_error == predicted_pipeline_error(grid, *frf, method, 4.0));
  }
}

TEST_CASE("extreme grids get a small proxy", "[pipeline_error]") {
  struct Case {
    Grid grid;
    double alpha;
  };
  const Case cases[] = {{Grid(1, 4096, 1e-3, 4.096), 12.0},     // one column of square cells
                        {Grid(4096, 1, 4.096, 1e-3), 12.0},     // one row
                        {Grid(64, 64, 1.0, 1e-4), 12.0},        // dx/dy = 1e4
                        {Grid(64, 64, 1e-4, 1.0), 2.0},         // dy/dx = 1e4
                        {Grid(4096, 4096, 4e-3, 40e-6), 12.0},  // dx/dy = 100 on 4096^2
                        {Grid(4096, 4096, 1.0, 1.0), 1.0 + 1.0 / 4096.0}};
  for (const Case& c : cases) {
    const PipelineErrorProxy proxy = pipeline_error_proxy(c.grid, c.alpha);
    const double a2 = std::max(proxy.alpha, 2.0);
    INFO(c.grid.nx() << " x " << c.grid.ny() << ", lx / ly = " << c.grid.lx() / c.grid.ly()
                     << ", alpha = " << c.alpha << ": proxy " << proxy.grid.nx() << " x "
                     << proxy.grid.ny() << ", alpha " << proxy.alpha);
    // At most twice the 2^19-point budget of the extended lattice, and alpha never raised.
    CHECK(a2 * a2 * static_cast<double>(proxy.grid.nb_cells()) <= 1048576.0);
    CHECK(proxy.alpha <= c.alpha);
    CHECK(proxy.alpha >= c.alpha - 0.125);
    for (const Method method : pipelines) {
      if (method == Method::frf_dcfft && c.alpha < 2.0) continue;  // frf-dcfft needs alpha >= 2
      const double e = predicted_pipeline_error(c.grid, method, c.alpha);
      CHECK(std::isfinite(e));
      CHECK(e > 0.0);
    }
  }
}

TEST_CASE("the reference load carries its force on coarse and elongated cells",
          "[pipeline_error]") {
  // Force of p = sqrt(1 - r^2/a^2): (2/3) pi a^2, with a = min(lx, ly)/3.
  for (const Grid& grid : {Grid(64, 64, 3.0, 3.0), Grid(64, 64, 4e-3, 40e-6), Grid(1, 1, 1.0, 1.0),
                           Grid(7, 5, 2.0, 1.0)}) {
    const double a = std::min(grid.lx(), grid.ly()) / 3.0;
    const Field p = pipeline_error_reference_load(grid);
    INFO(grid.nx() << " x " << grid.ny() << ", lx = " << grid.lx() << ", ly = " << grid.ly());
    CHECK(p.minCoeff() >= 0.0);
    CHECK(p.sum() * grid.dx() * grid.dy() ==
          Approx(2.0 / 3.0 * std::numbers::pi * a * a).epsilon(1e-2));
    // Centred: symmetric in x and in y.
    CHECK((p - p.colwise().reverse()).cwiseAbs().maxCoeff() <= 1e-14);
    CHECK((p - p.rowwise().reverse()).cwiseAbs().maxCoeff() <= 1e-14);
  }
}

TEST_CASE("the model refuses what make_operator refuses", "[pipeline_error]") {
  const Grid grid(32, 32, 1.0, 1.0);
  for (const Method method : {Method::direct, Method::dcfft, Method::frf_split})
    CHECK_THROWS_AS(predicted_pipeline_error(grid, method, 2.0), InvalidArgument);
  CHECK_THROWS_AS(predicted_pipeline_error(grid, Method::frf_dcfft, 1.5), InvalidArgument);
  CHECK_THROWS_AS(predicted_pipeline_error(grid, Method::frf_spectral, 0.5), InvalidArgument);
  CHECK_THROWS_AS(predicted_pipeline_error(grid, Method::frf_spectral, 2.01), InvalidArgument);
  CHECK_THROWS_AS(predicted_pipeline_error(grid, Method::frf_spectral, 2.0, 0), InvalidArgument);
}
