// The n-layer recursion against the closed forms (one coating), against itself under exact
// identities (splitting a layer, layers identical to the substrate), and make_frf / frf_table.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "frf/coated_frf.hpp"
#include "frf/frf_table.hpp"
#include "frf/half_space_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"
#include "tests/test_support.hpp"

using coatfft::CoatedFrf;
using coatfft::Coating;
using coatfft::HalfSpaceFrf;
using coatfft::Interface;
using coatfft::LayerStack;
using coatfft::Material;
using coatfft::MultilayerFrf;

namespace {}  // namespace

TEST_CASE("Multilayer with one coating equals the closed form (200 random stacks)",
          "[frf][multilayer]") {
  // Both routes are accurate to ~1e-15 against 60-digit references over these ranges (docs/frf.md);
  // 1e-12 leaves room for the platform's libm.
  std::mt19937_64 rng(20240503);
  std::uniform_real_distribution<double> log_ratio(-4.0, 4.0), nu(0.0, 0.4999), log_kh(-6.0, 5.0),
      log_h(-7.0, -3.0);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Material coating(2e11 * std::pow(10.0, log_ratio(rng)), nu(rng));
    const Material substrate(2e11, nu(rng));
    const double h = std::pow(10.0, log_h(rng));
    const double kh = std::pow(10.0, log_kh(rng));
    for (auto interface : {Interface::bonded, Interface::frictionless}) {
      const CoatedFrf closed(coating, h, substrate, interface);
      const MultilayerFrf multi(LayerStack({{coating, h, interface}}, substrate));
      const double e = rel_err(multi(kh / h), closed(kh / h));
      worst = std::max(worst, e);
      INFO("stack " << i << ": E1/E2 = " << coating.youngs_modulus() / 2e11
                    << ", nu1 = " << coating.poisson_ratio()
                    << ", nu2 = " << substrate.poisson_ratio() << ", kh = " << kh);
      CHECK(e <= 1e-12);
      CHECK(multi.c0() == closed.c0());
      CHECK(multi.c_inf() == closed.c_inf());
    }
  }
  WARN("multilayer vs closed form, worst relative difference: " << worst);
}

TEST_CASE("Two bonded coatings of one material equal one coating of summed thickness",
          "[frf][multilayer]") {
  const Material a(3e11, 0.22);
  const Material b(7e10, 0.35);
  for (auto bottom : {Interface::bonded, Interface::frictionless}) {
    const MultilayerFrf split(LayerStack({{a, 0.4e-6, Interface::bonded}, {a, 1.1e-6, bottom}}, b));
    const CoatedFrf whole(a, 1.5e-6, b, bottom);
    for (double k : {1e-2, 1e3, 1e5, 6e5, 1e6, 3e6, 1e8, 1e12}) {
      INFO("k = " << k);
      CHECK(rel_err(split(k), whole(k)) <= 1e-12);  // measured <= 1e-15
    }
  }
}

TEST_CASE("Layers identical to the substrate and bonded give the half-space", "[frf][multilayer]") {
  const Material m(1.5e9, 0.4);
  std::vector<Coating> coatings(5, Coating{m, 2e-6, Interface::bonded});
  const MultilayerFrf frf(LayerStack(coatings, m));
  const HalfSpaceFrf bare(m);
  for (double k : {1e-3, 1.0, 1e4, 1e5, 5e5, 1e6, 1e7, 1e9, 1e14}) {
    INFO("k = " << k);
    CHECK(rel_err(frf(k), bare(k)) <= 1e-13);
  }
  CHECK(MultilayerFrf(LayerStack(m)).name() == "multilayer");
  CHECK(rel_err(MultilayerFrf(LayerStack(m))(2.0), bare(2.0)) <= 1e-15);
}

TEST_CASE("Multilayer limits: substrate at kh -> 0, top coating at kh -> inf",
          "[frf][multilayer]") {
  const Material top(4e11, 0.25), mid(2e9, 0.45), bottom(7e10, 0.33), substrate(2.1e11, 0.3);
  const LayerStack stack({{top, 1e-6, Interface::bonded},
                          {mid, 5e-6, Interface::frictionless},
                          {bottom, 2e-6, Interface::bonded}},
                         substrate);
  const MultilayerFrf frf(stack);
  CHECK(frf.c0() == 2.0 / substrate.plane_strain_modulus());
  CHECK(frf.c_inf() == 2.0 / top.plane_strain_modulus());
  // k h_total = 8e-15: O(kh) deviation < 1e-12 for moduli contrasts of ~200.
  CHECK(rel_err(frf(1e-9) * 1e-9, frf.c0()) < 1e-12);
  CHECK(rel_err(frf(1e-300) * 1e-300, frf.c0()) < 1e-12);
  // k h_top = 60: the top coating alone to exp(-120).
  CHECK(rel_err(frf(6e7) * 6e7, frf.c_inf()) < 1e-12);
  CHECK(rel_err(frf(1e300) * 1e300, frf.c_inf()) < 1e-12);
}

TEST_CASE("Multilayer stays finite and positive for extreme stacks", "[frf][multilayer]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_ratio(-6.0, 6.0), nu(-0.9, 0.4999), log_k(-8.0, 8.0),
      unit(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    const int n = 1 + static_cast<int>(unit(rng) * 5);
    std::vector<Coating> coatings;
    for (int j = 0; j < n; ++j) {
      coatings.push_back({Material(std::pow(10.0, log_ratio(rng)), nu(rng)),
                          std::pow(10.0, -1.0 + 2.0 * unit(rng)),
                          unit(rng) < 0.5 ? Interface::bonded : Interface::frictionless});
    }
    const MultilayerFrf frf(LayerStack(coatings, Material(1.0, nu(rng))));
    for (double k : {std::pow(10.0, log_k(rng)), 1e-8, 1e8, 1e-200, 1e200}) {
      const double h = frf(k);  // throws (fails the test) if not finite and > 0
      CHECK((std::isfinite(h) && h > 0));
    }
  }
}

TEST_CASE("make_frf picks the cheapest exact class", "[frf]") {
  const Material a(4e11, 0.25), b(2.1e11, 0.3);
  CHECK(coatfft::make_frf(LayerStack(b))->name() == "half_space");
  CHECK(coatfft::make_frf(LayerStack({{a, 1e-6}}, b))->name() == "coated_bonded");
  CHECK(coatfft::make_frf(LayerStack({{a, 1e-6, Interface::frictionless}}, b))->name() ==
        "coated_frictionless");
  CHECK(coatfft::make_frf(LayerStack({{a, 1e-6}, {b, 1e-6}}, b))->name() == "multilayer");
}

TEST_CASE("frf_table is log-spaced with exact endpoints and consistent columns", "[frf]") {
  const Material a(4e11, 0.25), b(2.1e11, 0.3);
  const LayerStack stack({{a, 1e-6}, {b, 2e-6, Interface::frictionless}}, b);
  const auto frf = coatfft::make_frf(stack);
  const auto rows = coatfft::frf_table(stack, *frf, 1e2, 1e8, 13);
  REQUIRE(rows.size() == 13);
  CHECK(rows.front().k == 1e2);
  CHECK(rows.back().k == 1e8);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(rows[i].k == Approx(1e2 * std::pow(10.0, 0.5 * i)).epsilon(1e-14));
    CHECK(rows[i].kh_total == Approx(rows[i].k * 3e-6).epsilon(1e-15));
    CHECK(rows[i].frf == (*frf)(rows[i].k));
    CHECK(rows[i].ratio_to_substrate ==
          Approx(rows[i].frf * rows[i].k * b.plane_strain_modulus() / 2).epsilon(1e-15));
  }
  // Ends: the substrate (ratio 1) and the top coating (ratio E2*/E1*), to O(kh) and exp(-2kh).
  CHECK(rows.front().ratio_to_substrate == Approx(1.0).epsilon(1e-3));
  CHECK(rows.back().ratio_to_substrate ==
        Approx(b.plane_strain_modulus() / a.plane_strain_modulus()).epsilon(1e-12));
  CHECK_THROWS_AS(coatfft::frf_table(stack, *frf, 0.0, 1.0, 3), coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::frf_table(stack, *frf, 2.0, 1.0, 3), coatfft::InvalidArgument);
  CHECK_THROWS_AS(coatfft::frf_table(stack, *frf, 1.0, 2.0, 1), coatfft::InvalidArgument);
}
