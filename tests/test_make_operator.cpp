// make_operator: every method builds, reports what it built and the method it runs; bodies and
// options a method cannot take are refused before any work.
#include <catch2/catch.hpp>
#include <cmath>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "core/norms.hpp"
#include "frf/half_space_frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/catalog.hpp"

using namespace coatfft;

namespace {

const Grid grid(32, 24, 3e-3, 2.25e-3);
const LayerStack steel_stack(material_by_name("steel"));
const LayerStack coated_stack({Coating{material_by_name("titanium_nitride"), 20e-6,
                                       Interface::bonded}},
                              material_by_name("steel"));

OperatorOptions with(Method method, double alpha = 2.0) {
  OperatorOptions o;
  o.method = method;
  o.alpha = alpha;
  return o;
}

}  // namespace

TEST_CASE("make_operator builds every method and reports it", "[make_operator]") {
  const Field p = hertz_pressure(grid, 1e9, 1e-3, Sampling::cell_average);
  for (const Method method : all_methods) {
    const LayerStack& body = uses_love_coefficients(method) ? steel_stack : coated_stack;
    const double alpha = method == Method::frf_spectral ? 3.0 : 2.0;
    const BuiltOperator built = make_operator(grid, body, with(method, alpha));
    INFO(to_string(method));
    CHECK(built.op->method() == method);
    CHECK(built.op->name() == to_string(method));
    CHECK(built.report.method == method);
    CHECK(built.report.setup_seconds >= 0.0);
    // The kernel's time is part of the setup; frf-spectral has no kernel of its own.
    CHECK((built.report.kernel_seconds > 0.0) == (method != Method::frf_spectral));
    CHECK(built.report.kernel_seconds <= built.report.setup_seconds);
    CHECK(built.report.frf.empty() == uses_love_coefficients(method));
    CHECK(built.report.alpha.has_value() == samples_frf_lattice(method));
    CHECK(built.report.g0.has_value() == samples_frf_lattice(method));
    CHECK(built.report.split.has_value() == (method == Method::frf_split));
    // Transform lengths: DC-FFT's padded lattice, the extended lattice, none for the direct sum.
    const std::ptrdiff_t factor = method == Method::direct         ? 0
                                  : method == Method::frf_spectral ? 3
                                                                   : 2;
    CHECK(built.report.fft_nx == factor * grid.nx());
    CHECK(built.report.fft_ny == factor * grid.ny());
    const Field u = built.op->apply(p);
    CHECK(u.allFinite());
    CHECK(u.maxCoeff() > 0.0);
  }
}

TEST_CASE("make_operator: frf-split on a half-space is Love's DC-FFT", "[make_operator]") {
  // The split kernel of a homogeneous FRF is Love's coefficients exactly (docs/split_kernel.md);
  // the two operators differ by FFT rounding only (~eps log2(4 nx ny)).
  const Field p = hertz_pressure(grid, 1e9, 1e-3, Sampling::centre);
  const Field love = make_operator(grid, steel_stack, with(Method::dcfft)).op->apply(p);
  const Field split = make_operator(grid, steel_stack, with(Method::frf_split)).op->apply(p);
  CHECK(rel_linf(split, love) < 1e-13);
  // The same through the Frf overload (a user's FRF): the half-space FRF of the same material.
  const HalfSpaceFrf frf(material_by_name("steel"));
  const Field from_frf = make_operator(grid, frf, with(Method::frf_split)).op->apply(p);
  CHECK(rel_linf(from_frf, love) < 1e-13);
}

TEST_CASE("make_operator refuses what a method cannot take", "[make_operator][bad_input]") {
  CHECK_THROWS_WITH(make_operator(grid, coated_stack, with(Method::dcfft)),
                    Catch::Contains("homogeneous half-space"));
  CHECK_THROWS_WITH(make_operator(grid, coated_stack, with(Method::direct)),
                    Catch::Contains("homogeneous half-space"));
  const HalfSpaceFrf frf(material_by_name("steel"));
  CHECK_THROWS_WITH(make_operator(grid, frf, with(Method::dcfft)), Catch::Contains("an FRF alone"));
  OperatorOptions o = with(Method::frf_spectral, 2.5);  // 2.5 * 24 cells is whole, 2.5 * 32 too
  CHECK_NOTHROW(check_operator_options(grid, o));
  o.alpha = 2.3;
  CHECK_THROWS_WITH(check_operator_options(grid, o), Catch::Contains("whole numbers"));
  o = with(Method::frf_dcfft, 1.5);
  CHECK_THROWS_WITH(check_operator_options(grid, o), Catch::Contains("frf-dcfft needs alpha >= 2"));
  o = with(Method::dcfft, 0.5);
  CHECK_THROWS_WITH(check_operator_options(grid, o), Catch::Contains("alpha = 0.5 must be >= 1"));
  o = with(Method::dcfft);
  for (const int threads : {0, 257}) {
    o.threads = threads;
    CHECK_THROWS_WITH(check_operator_options(grid, o), Catch::Contains("must be in 1..256"));
  }
  o = with(Method::frf_spectral);
  for (const double tolerance : {0.0, 1.0, std::nan("")}) {
    o.g0_tolerance = tolerance;
    CHECK_THROWS_AS(make_operator(grid, coated_stack, o), InvalidArgument);
  }
}

TEST_CASE("method names round-trip and unknown names are refused", "[make_operator]") {
  for (const Method method : all_methods) CHECK(parse_method(to_string(method)) == method);
  CHECK_THROWS_WITH(parse_method("frf_split"),
                    Catch::Equals("\"frf_split\" is not one of \"direct\", \"dcfft\", "
                                  "\"frf-spectral\", \"frf-dcfft\", \"frf-split\""));
}
