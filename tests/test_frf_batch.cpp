// Frf::evaluate, the batch form of an FRF: the pipelines that sample many wavenumbers ask for them
// in batches (one per lattice column or table), so that an FRF with a cost per call (a Python
// callable of a numpy array) is called a few hundred times rather than tens of thousands; the
// results are those of the built-in FRF's own operator().
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "frf/frf.hpp"
#include "frf/frf_table.hpp"
#include "frf/half_space_frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/catalog.hpp"

using namespace coatfft;

namespace {

// Forwards to `inner` and counts how it is asked: single operator() calls, evaluate() calls and
// the wavenumbers of those. The batches forward to inner.evaluate, the default, which calls
// inner's operator() (not this one's): every H is the double the built-in gives at that k.
// Atomic: the pipelines call from their worker threads.
class CountingFrf final : public Frf {
 public:
  explicit CountingFrf(const Frf& inner) : inner_(inner) {}
  double operator()(double k) const override {
    ++singles;
    return inner_(k);
  }
  void evaluate(std::span<const double> k, std::span<double> h) const override {
    ++batches;
    points += k.size();
    inner_.evaluate(k, h);
  }
  double c0() const override { return inner_.c0(); }
  double c_inf() const override { return inner_.c_inf(); }
  std::string name() const override { return inner_.name(); }

  mutable std::atomic<std::size_t> singles{0};
  mutable std::atomic<std::size_t> batches{0};
  mutable std::atomic<std::size_t> points{0};

 private:
  const Frf& inner_;
};

// Gives the inner FRF's values one at a time, but a NaN as the last value of every batch.
class BadBatchFrf final : public Frf {
 public:
  explicit BadBatchFrf(const Frf& inner) : inner_(inner) {}
  double operator()(double k) const override { return inner_(k); }
  void evaluate(std::span<const double> k, std::span<double> h) const override {
    inner_.evaluate(k, h);
    if (!h.empty()) h.back() = std::nan("");
  }
  double c0() const override { return inner_.c0(); }
  double c_inf() const override { return inner_.c_inf(); }
  std::string name() const override { return "bad_batch"; }

 private:
  const Frf& inner_;
};

// TiN (titanium_nitride) 2 um on steel under a Hertz load of radius a = 20 um (a/h = 10: the
// coating moves u by 2.7 % of max |u| from steel's, checked below, so the FRF's values matter);
// 64 x 64 cells over 3a x 3a.
LayerStack coated_body() {
  return LayerStack({{material_by_name("titanium_nitride"), 2e-6, Interface::bonded}},
                    material_by_name("steel"));
}
constexpr double a = 20e-6;
const Grid grid(64, 64, 3 * a, 3 * a);
Field hertz_load() {
  return hertz_pressure(grid, 1e9, a, Sampling::centre);
}

Field displacement(const Frf& frf, Method method, int threads = 1) {
  OperatorOptions o;
  o.method = method;
  o.threads = threads;
  return make_operator(grid, frf, o).op->apply(hertz_load());
}

}  // namespace

// Measured on this case (g(0) regularized at 1e-10, alpha = 2, threads = 1, split defaults):
//   method        single operator() calls   evaluate() calls   wavenumbers in them
//   frf-spectral  127                       138                12290
//   frf-dcfft     127                       138                12290
//   frf-split       3                         9                10455
// frf-spectral and frf-dcfft sample the same 65 x 65 quarter: one batch per column (64, 64, 63,
// ..., 1: the lower triangle, 2144 wavenumbers). The predicted error (make_operator's report)
// samples it again on its proxy (this very grid: 65 batches, 2144), after one batch of 32 that
// finds the coating too thick for the homogeneous model and a split kernel on the proxy (7
// batches, 7970). Their single calls are the two g(0) integrals (GSL's adaptive QAG, one point
// at a time by design: 62 each) and the split kernel's 3. frf-split: its scan of k H (136), its
// table of R (3951), the Hankel panels (704) and two rounds of short-range tables and midpoint
// checks (5664); its single calls are the searches for the ends of its scan (at least one
// each).
TEST_CASE("the FRF pipelines sample in batches and give the built-in FRF's displacement",
          "[frf][batch]") {
  const std::unique_ptr<Frf> builtin = make_frf(coated_body());
  // The quarter of the alpha = 2 lattice: 65 columns; its lower triangle less the singular (0, 0).
  const std::size_t columns = 64 + 1, lattice_points = columns * (columns + 1) / 2 - 1;
  for (const Method method : {Method::frf_spectral, Method::frf_dcfft, Method::frf_split}) {
    CAPTURE(to_string(method));
    const CountingFrf counting(*builtin);
    const Field u = displacement(counting, method);
    const Field reference = displacement(*builtin, method);
    // Bit-identical: both FRFs give the same double at every k (the wrapper's batch ends in the
    // built-in's operator(), as the built-in's default evaluate does), and the pipeline's
    // arithmetic on those values is the same whichever form the FRF overrides.
    REQUIRE(u.rows() == 64);
    REQUIRE((u == reference).all());
    const std::size_t singles = counting.singles, batches = counting.batches,
                      points = counting.points;
    CAPTURE(singles, batches, points);
    // Nearly every wavenumber comes in a batch (measured: 97x and 3500x the single calls).
    CHECK(points >= 20 * singles);
    if (method == Method::frf_split) {
      // Scan, table, Hankel panels, and at most 10 rounds of 2 batches on each of the 2
      // short-range segments: one call per point would be thousands.
      CHECK(batches <= 3 + 2 * 10 * 2);
      CHECK(singles <= 14);  // the two end searches of the scan, at most 7 points each
    } else {
      // The whole lattice through batches, one per column and lattice (the operator's and the
      // predicted error's), plus a few.
      CHECK(points >= lattice_points);
      CHECK(batches <= 3 * columns);
    }
  }
}

TEST_CASE("the coating changes the displacement, so the comparison above tests the FRF",
          "[frf][batch]") {
  const std::unique_ptr<Frf> coated = make_frf(coated_body());
  const HalfSpaceFrf steel(material_by_name("steel"));
  const Field u = displacement(*coated, Method::frf_spectral);
  const Field u_steel = displacement(steel, Method::frf_spectral);
  CHECK((u - u_steel).abs().maxCoeff() > 1e-2 * u_steel.abs().maxCoeff());
}

TEST_CASE("results do not depend on the threads that evaluate the batches", "[frf][batch]") {
  const std::unique_ptr<Frf> builtin = make_frf(coated_body());
  const CountingFrf counting(*builtin);
  for (const Method method : {Method::frf_spectral, Method::frf_split}) {
    CAPTURE(to_string(method));
    CHECK((displacement(counting, method, 2) == displacement(*builtin, method, 1)).all());
  }
}

TEST_CASE("frf_table asks for its wavenumbers in one batch", "[frf][batch]") {
  const LayerStack body = coated_body();
  const std::unique_ptr<Frf> builtin = make_frf(body);
  const CountingFrf counting(*builtin);
  const std::vector<FrfTableRow> rows = frf_table(body, counting, 1e2, 1e8, 61);
  CHECK(counting.singles == 0);
  CHECK(counting.batches == 1);
  CHECK(counting.points == 61);
  REQUIRE(rows.size() == 61);
  for (const FrfTableRow& row : rows) CHECK(row.frf == (*builtin)(row.k));
}

TEST_CASE("the split kernel checks every value of a batch", "[frf][batch][bad_input]") {
  const std::unique_ptr<Frf> builtin = make_frf(coated_body());
  const BadBatchFrf bad(*builtin);
  OperatorOptions o;
  o.method = Method::frf_split;
  REQUIRE_THROWS_AS(make_operator(grid, bad, o), InvalidArgument);
  REQUIRE_THROWS_WITH(make_operator(grid, bad, o),
                      Catch::Matchers::Contains("the FRF 'bad_batch' gives H(") &&
                          Catch::Matchers::Contains("nan m/Pa, but it must be finite and > 0"));
}

TEST_CASE("the default evaluate gives operator()'s values and refuses mismatched sizes",
          "[frf][batch][bad_input]") {
  const std::unique_ptr<Frf> builtin = make_frf(coated_body());
  const std::vector<double> k = {1e3, 1e5, 5e5, 1e7};
  std::vector<double> h(k.size());
  builtin->evaluate(k, h);
  for (std::size_t i = 0; i < k.size(); ++i) CHECK(h[i] == (*builtin)(k[i]));
  builtin->evaluate(std::span<const double>(), std::span<double>());  // empty: nothing to do
  std::vector<double> short_h(k.size() - 1, -1.0);
  REQUIRE_THROWS_AS(builtin->evaluate(k, short_h), InvalidArgument);
  REQUIRE_THROWS_WITH(builtin->evaluate(k, short_h),
                      Catch::Matchers::Contains("4 wavenumbers but 3 outputs"));
  // Refused before any value is written.
  CHECK(std::all_of(short_h.begin(), short_h.end(), [](double v) { return v == -1.0; }));
}
