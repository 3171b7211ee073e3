// TabulatedFrf (frf/tabulated_frf.hpp) against coatfft's exact FRFs sampled into tables: the
// interpolation error against the table's density, the extensions beyond the table, the estimate
// of c0 and c_inf, refusals of bad tables, and concurrent evaluation.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/tabulated_frf.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"

using Catch::Matchers::Contains;
using coatfft::Coating;
using coatfft::Frf;
using coatfft::Interface;
using coatfft::InvalidArgument;
using coatfft::LayerStack;
using coatfft::Material;
using coatfft::TabulatedFrf;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const Material steel(210e9, 0.3), tin(400e9, 0.25), peek(3.7e9, 0.4), ptfe(0.5e9, 0.46),
    wc(600e9, 0.22), aluminium(68.9e9, 0.33), alumina(416e9, 0.231);

// Stiff and soft coatings, bonded and frictionless, and two three-layer stacks with a soft
// frictionless interlayer (where k H need not be monotone): the hardest to interpolate.
std::vector<LayerStack> bodies() {
  return {LayerStack({{tin, 1e-6, Interface::bonded}}, steel),
          LayerStack({{tin, 1e-6, Interface::frictionless}}, steel),
          LayerStack({{peek, 1e-6, Interface::bonded}}, steel),
          LayerStack({{wc, 1e-6, Interface::bonded}}, ptfe),
          LayerStack({{wc, 1e-6, Interface::frictionless}}, peek),
          LayerStack({{tin, 1e-6, Interface::bonded},
                      {peek, 2e-6, Interface::frictionless},
                      {wc, 0.5e-6, Interface::bonded}},
                     aluminium),
          LayerStack({{tin, 3e-5, Interface::bonded},
                      {peek, 5e-5, Interface::frictionless},
                      {alumina, 2e-5, Interface::bonded}},
                     steel)};
}

// `frf` at n log-spaced points per decade over k h = kh_min .. kh_max.
struct Samples {
  std::vector<double> k, H;
};
Samples sample(const Frf& frf, double h, int per_decade, double kh_min, double kh_max) {
  Samples s;
  const auto n = static_cast<int>(std::lround(std::log10(kh_max / kh_min) * per_decade));
  for (int i = 0; i <= n; ++i) {
    const double k = kh_min / h * std::pow(10.0, static_cast<double>(i) / per_decade);
    s.k.push_back(k);
    s.H.push_back(frf(k));
  }
  return s;
}

// Largest relative error of `table` against `exact` at 7 points inside each interval of the
// table's k (1/8 .. 7/8 of the way in ln k).
double worst_between(const TabulatedFrf& table, const Frf& exact) {
  const std::vector<double>& k = table.k();
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < k.size(); ++i)
    for (int s = 1; s < 8; ++s) {
      const double x = std::exp(std::log(k[i]) + std::log(k[i + 1] / k[i]) * s / 8.0);
      worst = std::max(worst, std::abs(table(x) / exact(x) - 1.0));
    }
  return worst;
}

std::unique_ptr<TabulatedFrf> table_of(const Frf& exact, double h, int per_decade, double kh_min,
                                       double kh_max, bool give_limits) {
  Samples s = sample(exact, h, per_decade, kh_min, kh_max);
  if (!give_limits) return std::make_unique<TabulatedFrf>(std::move(s.k), std::move(s.H));
  return std::make_unique<TabulatedFrf>(std::move(s.k), std::move(s.H), exact.c0(), exact.c_inf());
}

}  // namespace

TEST_CASE("TabulatedFrf: interpolation error against points per decade", "[frf][table]") {
  // The bounds are the largest errors measured over bodies() (rounded up to two digits), the
  // numbers docs/frf.md and frf/tabulated_frf.hpp state; the reference is the exact FRF the
  // table was sampled from (closed form or recursion, docs/frf.md: accurate to 1e-13).
  struct Row {
    int per_decade;
    double bound;
  };
  double previous = 0.0;
  for (const Row row :
       {Row{10, 1.4e-3}, Row{20, 5.9e-5}, Row{40, 3.3e-6}, Row{80, 2.0e-7}, Row{160, 1.3e-8}}) {
    double worst = 0.0;
    for (const LayerStack& body : bodies()) {
      const auto exact = coatfft::make_frf(body);
      const double h = body.total_thickness();
      const auto table = table_of(*exact, h, row.per_decade, 1e-8, 1e3, true);
      worst = std::max(worst, worst_between(*table, *exact));
    }
    INFO("points per decade " << row.per_decade << ": worst relative error " << worst);
    CHECK(worst <= row.bound);
    // A cubic spline converges like (ln 10 / n)^4: 16 times per doubling, at least 12 here.
    if (previous > 0) CHECK(previous / worst > 12.0);
    previous = worst;
  }
}

TEST_CASE("TabulatedFrf: exact at its points, continuous extensions beyond them", "[frf][table]") {
  const LayerStack body({{tin, 1e-6, Interface::bonded}}, steel);
  const auto exact = coatfft::make_frf(body);
  const auto table = table_of(*exact, 1e-6, 20, 1e-8, 1e3, true);
  for (std::size_t i = 0; i < table->size(); ++i)
    CHECK(std::abs((*table)(table->k()[i]) / table->H()[i] - 1.0) <= 4 * eps);
  // Below k_min (k h = 1e-8) H = C0/k + O(1): the linear extension of k H is off by O((k h)^2).
  const double k_min = table->k().front();
  for (const double k : {0.5 * k_min, 1e-3 * k_min, 1e-12 * k_min})
    CHECK(std::abs((*table)(k) / (*exact)(k)-1.0) <= 1e-14);
  // Above k_max (k h = 1e3) the exact k H is Cinf to rounding, and so is the extension.
  const double k_max = table->k().back();
  for (const double k : {2.0 * k_max, 1e6 * k_max})
    CHECK(std::abs((*table)(k) / (*exact)(k)-1.0) <= 4 * eps);
  // A table short of the limits: given c0 and c_inf, the extensions run from the end values to
  // them continuously (no jump at k_min or k_max).
  const auto short_table = table_of(*exact, 1e-6, 20, 1e-2, 1e1, true);
  const double lo = short_table->k().front(), hi = short_table->k().back();
  CHECK((*short_table)(std::nextafter(lo, 0.0)) == Approx((*short_table)(lo)).epsilon(1e-12));
  CHECK((*short_table)(std::nextafter(hi, 2 * hi)) == Approx((*short_table)(hi)).epsilon(1e-12));
  CHECK(1e-9 * lo * (*short_table)(1e-9 * lo) == Approx(exact->c0()).epsilon(1e-8));
  CHECK(1e3 * hi * (*short_table)(1e3 * hi) == Approx(exact->c_inf()).epsilon(1e-14));
  CHECK(table->name() == "table");
}

TEST_CASE("TabulatedFrf: a homogeneous table is 2/(E* k) to rounding", "[frf][table]") {
  const auto exact = coatfft::make_frf(LayerStack(steel));
  // Any density: k H is constant up to the rounding of k and H, which the spline carries over.
  const auto table = table_of(*exact, 1.0, 5, 1e-3, 1e6, false);
  CHECK(worst_between(*table, *exact) <= 8 * eps);
  CHECK(table->c0() == Approx(exact->c0()).epsilon(4 * eps));
  CHECK(table->c_inf() == Approx(exact->c_inf()).epsilon(4 * eps));
}

TEST_CASE("TabulatedFrf: c0 and c_inf estimated from flat ends, refused otherwise",
          "[frf][table]") {
  const LayerStack body({{tin, 1e-6, Interface::bonded}}, steel);
  const auto exact = coatfft::make_frf(body);
  // Reaching k h = 1e-9, k H = C0 (1 + O(k h)) is flat to ~1e-9 over the first decade: the end
  // value is C0 to that. At k h = 1e3, exp(-2 k h) underflows: k H is Cinf to rounding.
  const auto estimated = table_of(*exact, 1e-6, 20, 1e-9, 1e3, false);
  CHECK(estimated->c0_estimated());
  CHECK(estimated->c_inf_estimated());
  CHECK(estimated->c0() == Approx(exact->c0()).epsilon(1e-8));
  CHECK(estimated->c_inf() == Approx(exact->c_inf()).epsilon(4 * eps));
  const auto given = table_of(*exact, 1e-6, 20, 1e-9, 1e3, true);
  CHECK_FALSE(given->c0_estimated());
  CHECK_FALSE(given->c_inf_estimated());
  CHECK(given->c0() == exact->c0());
  CHECK(given->c_inf() == exact->c_inf());

  // Ends short of the limits: the estimate is refused, naming the limit and what to give.
  Samples low = sample(*exact, 1e-6, 20, 1e-3, 1e3);
  CHECK_THROWS_WITH(TabulatedFrf(low.k, low.H), Contains("small-k limit") && Contains("give c0"));
  CHECK_NOTHROW(TabulatedFrf(low.k, low.H, exact->c0()));
  Samples high = sample(*exact, 1e-6, 20, 1e-9, 1e0);
  CHECK_THROWS_WITH(TabulatedFrf(high.k, high.H),
                    Contains("large-k limit") && Contains("give c_inf"));
  CHECK_NOTHROW(TabulatedFrf(high.k, high.H, std::nullopt, exact->c_inf()));
}

TEST_CASE("TabulatedFrf refuses bad tables, naming the row and the value", "[frf][table]") {
  const std::vector<double> k{1, 10, 100, 1000, 10000, 100000};
  const std::vector<double> H{2, 0.2, 0.02, 0.002, 0.0002, 0.00002};
  CHECK_NOTHROW(TabulatedFrf(k, H));
  auto with = [](std::vector<double> v, std::size_t i, double value) {
    v[i] = value;
    return v;
  };
  CHECK_THROWS_WITH(TabulatedFrf(with(k, 3, 50), H),
                    Contains("row 3: k = 50") && Contains("strictly ascending"));
  CHECK_THROWS_WITH(TabulatedFrf(with(k, 2, 10), H), Contains("row 2: k = 10"));
  CHECK_THROWS_WITH(TabulatedFrf(k, with(H, 4, -1e-4)), Contains("row 4: H = -1e-04"));
  CHECK_THROWS_WITH(TabulatedFrf(k, with(H, 1, NAN)), Contains("row 1: H = nan"));
  CHECK_THROWS_WITH(TabulatedFrf(with(k, 0, INFINITY), H), Contains("row 0: k = inf"));
  CHECK_THROWS_WITH(TabulatedFrf({1, 2, 3, 4}, {1, 0.5, 0.3, 0.25}),
                    Contains("4 rows") && Contains("at least 5"));
  CHECK_THROWS_WITH(TabulatedFrf(k, {1, 2}), Contains("6 values of k but 2 of H"));
  CHECK_THROWS_WITH(TabulatedFrf(with(k, 5, 1e300), with(H, 5, 1e10)),
                    Contains("row 5: k H = 1e+300 * 1e+10 is out of the range"));
  CHECK_THROWS_WITH(TabulatedFrf(k, H, -1.0), Contains("c0 = -1"));
  CHECK_THROWS_WITH(TabulatedFrf(k, H, 2.0, 0.0), Contains("c_inf = 0"));
  // k H = 1, 1, 100, 1, 1, 1: the spline through the spike swings below zero beside it.
  CHECK_THROWS_WITH(TabulatedFrf(k, {1, 0.1, 1, 0.001, 0.0001, 0.00001}, 1.0, 1.0),
                    Contains("H must stay > 0") && Contains("add rows"));
  const TabulatedFrf table(k, H);
  CHECK_THROWS_AS(table(0.0), InvalidArgument);
  CHECK_THROWS_AS(table(-1.0), InvalidArgument);
  CHECK_THROWS_AS(table(NAN), InvalidArgument);
  CHECK_THROWS_WITH(table(1e-320), Contains("overflows"));
}

TEST_CASE("TabulatedFrf evaluates from several threads at once", "[frf][table]") {
  const LayerStack body({{peek, 1e-6, Interface::bonded}}, steel);
  const auto exact = coatfft::make_frf(body);
  const auto table = table_of(*exact, 1e-6, 40, 1e-8, 1e3, true);
  // The reference is the serial evaluation: no state may carry over between calls.
  std::vector<double> ks;
  for (int i = 0; i < 20000; ++i) ks.push_back(1e-2 * std::pow(10.0, 1e-3 * i * 0.61));
  std::vector<double> serial;
  for (const double k : ks) serial.push_back((*table)(k));
  constexpr int nb_threads = 4;
  std::vector<std::vector<double>> results(nb_threads, std::vector<double>(ks.size()));
  std::vector<std::thread> threads;
  for (int t = 0; t < nb_threads; ++t)
    threads.emplace_back([&, t] {
      // Each thread walks the table in its own order, so that a shared search cache would miss.
      for (std::size_t j = 0; j < ks.size(); ++j) {
        const std::size_t i = t % 2 == 0 ? j : ks.size() - 1 - j;
        results[t][i] = (*table)(ks[i]);
      }
    });
  for (std::thread& thread : threads) thread.join();
  for (const auto& result : results) CHECK(result == serial);
}

TEST_CASE("TabulatedFrf: given limits that contradict the table's ends are refused or warned",
          "[frf][table]") {
  const LayerStack body({{tin, 1e-6, Interface::bonded}}, steel);
  const auto exact = coatfft::make_frf(body);
  const Samples s = sample(*exact, 1e-6, 20, 1e-9, 1e3);
  const double c0 = exact->c0(), c_inf = exact->c_inf();
  // The true limits: the ends reach them, nothing to say.
  CHECK(TabulatedFrf(s.k, s.H, c0, c_inf).warnings().empty());
  // A limit 1e8 times off (a unit slip) made uz thousands of times too large, silently.
  CHECK_THROWS_WITH(TabulatedFrf(s.k, s.H, 1e8 * c0, c_inf),
                    Contains("c0 = ") && Contains("factor 1e+08") && Contains("contradict"));
  CHECK_THROWS_WITH(TabulatedFrf(s.k, s.H, c0, 1e-8 * c_inf),
                    Contains("c_inf = ") && Contains("factor 1e+08") && Contains("contradict"));
  CHECK_THROWS_AS(TabulatedFrf(s.k, s.H, c0 / 11.0, c_inf), InvalidArgument);
  CHECK_NOTHROW(TabulatedFrf(s.k, s.H, c0 / 9.0, c_inf));
  // 5 % off: kept, with one warning naming the limit.
  const TabulatedFrf off(s.k, s.H, 1.05 * c0, c_inf);
  REQUIRE(off.warnings().size() == 1);
  CHECK_THAT(off.warnings()[0], Contains("c0 = ") && Contains("differ by 5"));
  const TabulatedFrf both(s.k, s.H, 0.98 * c0, 1.02 * c_inf);
  CHECK(both.warnings().size() == 2);
  CHECK(TabulatedFrf(s.k, s.H, 1.005 * c0, c_inf).warnings().empty());
}
