// Coated FRFs against the 40-digit values of tests/data/frf_values.csv (168 values from a 40-digit
// solver, kept in the repository so that a clone runs its tests alone; one coating
// of thickness h = 1 on a substrate, k = t; columns C = H_zz E1* k/2, LLn = H_LL mu1 k/(1 - nu1),
// ZLn = 2 H_ZL mu1 k). The file is read at test time; the values were produced from the
// double-rounded inputs (E, nu, t as doubles), which we confirmed with an independent 50-digit
// global-matrix solve (agreement <= 6e-17), so the doubles parsed here are the right inputs.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frf/coated_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"
#include "tests/test_support.hpp"

using coatfft::CoatedFrf;
using coatfft::Interface;
using coatfft::LayerStack;
using coatfft::Material;
using coatfft::MultilayerFrf;

namespace {

struct Row {
  std::string set;
  double E1, nu1, E2, nu2;
  Interface interface;
  double t, C, LLn, ZLn;
};

std::vector<Row> read_rows() {
  const std::filesystem::path path =
      std::filesystem::path(COATFFT_SOURCE_DIR) / "tests" / "data" / "frf_values.csv";
  std::ifstream in(path);
  if (!in) FAIL("cannot open " << path.string());
  std::string line;
  // The file has CRLF line endings; drop the '\r' so that the last column parses cleanly.
  const auto next_line = [&in, &line]() {
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  };
  next_line();
  REQUIRE(line == "set,E1,nu1,E2,nu2,interface,t,C,LLn,ZLn,TTn");
  std::vector<Row> rows;
  while (next_line()) {
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    REQUIRE(f.size() == 11);
    REQUIRE((f[5] == "bonded" || f[5] == "frictionless"));
    rows.push_back({f[0], std::stod(f[1]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]),
                    f[5] == "bonded" ? Interface::bonded : Interface::frictionless, std::stod(f[6]),
                    std::stod(f[7]), std::stod(f[8]), std::stod(f[9])});
  }
  return rows;
}

}  // namespace

TEST_CASE("frf_values.csv: closed forms and multilayer recursion to 1e-12", "[frf][csv]") {
  const std::vector<Row> rows = read_rows();
  REQUIRE(rows.size() == 168);
  double worst_closed = 0.0, worst_multi = 0.0, worst_ll = 0.0, worst_zl = 0.0;
  for (const Row& r : rows) {
    const Material coating(r.E1, r.nu1);
    const Material substrate(r.E2, r.nu2);
    INFO(r.set << " " << (r.interface == Interface::bonded ? "bonded" : "frictionless")
               << " t = " << r.t);
    // The file's own consistency: C(0) = E1*/E2* and C(inf) = 1 within O(t) and O(t^2 e^-2t).
    if (r.t <= 1e-6)
      CHECK(rel_err(r.C, r.E1 / (1 - r.nu1 * r.nu1) * (1 - r.nu2 * r.nu2) / r.E2) < 1e-4);
    if (r.t >= 50) CHECK(r.C == 1.0);

    const CoatedFrf closed(coating, 1.0, substrate, r.interface);
    const MultilayerFrf multi(LayerStack({{coating, 1.0, r.interface}}, substrate));
    const double e_closed = rel_err(closed.factor(r.t), r.C);
    const double e_closed_h =
        rel_err(closed(r.t), 2.0 * r.C / (coating.plane_strain_modulus() * r.t));
    const Eigen::Matrix2d M = multi.surface_compliance(r.t);
    const double e_multi = rel_err(M(1, 1) * coating.plane_strain_modulus() * r.t / 2.0, r.C);
    const double mu1 = coating.shear_modulus();
    const double e_ll = rel_err(M(0, 0) * mu1 * r.t / (1 - r.nu1), r.LLn);
    // ZL is a small difference of O(1) quantities when nu1 -> 1/2 (ZLn -> 1 - 2 nu1 = 2e-4 for
    // set S2), so it is held to an absolute 1e-14 on the O(1) scale of the normalised compliance.
    const double e_zl = std::abs(2.0 * M(1, 0) * mu1 * r.t - r.ZLn);
    CHECK(e_closed <= 1e-12);
    CHECK(e_closed_h <= 1e-12);
    CHECK(e_multi <= 1e-12);
    CHECK(e_ll <= 1e-12);
    CHECK(e_zl <= 1e-14);
    worst_closed = std::max(worst_closed, e_closed);
    worst_multi = std::max(worst_multi, e_multi);
    worst_ll = std::max(worst_ll, e_ll);
    worst_zl = std::max(worst_zl, e_zl);
  }
  WARN("frf_values.csv worst errors: closed form C "
       << worst_closed << ", multilayer C " << worst_multi << ", multilayer LLn " << worst_ll
       << ", ZLn (abs) " << worst_zl);
}
