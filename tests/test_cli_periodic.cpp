// [grid] boundary = "periodic" in scenes: a rough periodic contact made with `coatfft surface`,
// Westergaard's wavy contact through the command line, and the refusals of what periodic
// surfaces do not support (one line, exit 2, no output).
#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>

#include "io/npy.hpp"
#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

const std::string kPeriodicHertz = R"([grid]
nx = 64
ny = 64
lx = 3.0e-3
ly = 3.0e-3
boundary = "periodic"
[substrate]
material = "steel"
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
)";

}  // namespace

TEST_CASE("a periodic wavy contact from the command line is Westergaard's", "[cli_periodic]") {
  // h = Delta (1 - cos(2 pi x/lambda)) as a height map, one period over 1024 x 2 cells; at
  // p_m = p*/2 (p* = pi E* Delta/lambda) Johnson's (1985, section 13.2) contact covers half the
  // period and the peak pressure is 2 sqrt(p_m p*) = sqrt(2) p*.
  const int n = 1024;
  const double lambda = 1e-3, delta = 1e-6, e_star = 210e9 / (1 - 0.09);
  coatfft::Field h(n, 2);
  for (int i = 0; i < n; ++i)
    h.row(i).setConstant(delta * (1 - std::cos(2 * std::numbers::pi * (i + 0.5 - n / 2) / n)));
  const fs::path gap = scratch("wavy_gap.npy");
  coatfft::io::write_npy(gap, h);
  const double p_star = std::numbers::pi * e_star * delta / lambda;
  const double load = 0.5 * p_star * lambda * (2 * lambda / n);
  std::ostringstream scene;
  scene << std::setprecision(17) << "[grid]\nnx = 1024\nny = 2\nlx = 1e-3\nly = " << 2 * lambda / n
        << "\nboundary = \"periodic\"\n[substrate]\nmaterial = \"steel\"\n"
        << "[contact]\nindenter = \"height_map\"\npath = \"" << gap.string()
        << "\"\nload = " << load << "\n";
  const nlohmann::json s = read_summary(run_scene_ok(scene.str(), "wavy"));
  CHECK(s["boundary"] == "periodic");
  CHECK(s["converged"] == true);
  const double width = s["contact_area"].get<double>() / (2 * lambda / n) / lambda;
  CHECK(std::abs(width - 0.5) <= 1.5 / n);
  CHECK(s["max_pressure"].get<double>() == Approx(std::sqrt(2.0) * p_star).epsilon(1e-4));
}

TEST_CASE("a rough periodic contact made with coatfft surface", "[cli_periodic]") {
  const fs::path z = scratch("rough_z.npy");
  fs::remove(z);
  REQUIRE(run_coatfft("surface -o " + z.string() +
                      " --nx 128 --ny 128 --lx 1e-3 --ly 1e-3 --hurst 0.8 --rms-height 0.5e-6 "
                      "--short-cutoff 3.2e-5 --seed 5")
              .status == 0);
  const coatfft::Field topography = coatfft::io::read_npy(z);
  const fs::path gap = scratch("rough_gap.npy");
  coatfft::io::write_npy(gap, topography.maxCoeff() - topography);
  const std::string scene =
      "[grid]\nnx = 128\nny = 128\nlx = 1e-3\nly = 1e-3\nboundary = \"periodic\"\n"
      "[substrate]\nmaterial = \"steel\"\n[[coating]]\nmaterial = \"titanium_nitride\"\n"
      "thickness = 5e-5\n[contact]\nindenter = \"height_map\"\npath = \"" +
      gap.string() + "\"\nload = 20.0\n";
  const fs::path out = run_scene_ok(scene, "rough_periodic");
  const nlohmann::json s = read_summary(out);
  CHECK(s["method"] == "frf-split");  // auto on a coated periodic body
  CHECK(s["method_requested"] == "auto");
  CHECK(s["converged"] == true);
  // A few per cent of the area in contact at 20 MPa mean pressure; the load is carried.
  CHECK(s["contact_area"].get<double>() > 0.0);
  CHECK(s["contact_area"].get<double>() < 0.2e-6);
  CHECK(s["total_load"].get<double>() == Approx(20.0).epsilon(1e-9));
  // The solve's applications: one per iteration, two in those that changed the contact set, and
  // the start's trial.
  const int iterations = s["iterations"].get<int>();
  const int applications = s["operator_applications"].get<int>();
  CHECK(applications > iterations);
  CHECK(applications <= 2 * iterations + 1);
}

TEST_CASE("a sliding rough periodic contact on a coated body, with its interface stresses",
          "[cli_periodic]") {
  // Full sliding (mu = 0.3) of a rigid rough flat over TiN 20 um on steel: the tractions' normal
  // displacement couples into the gap (a compressible, layered body) and the normal problem is
  // solved again until the pressure settles; the in-plane displacements have zero mean over the
  // period, as every periodic displacement; the stresses on the interface from both sides.
  const fs::path z = scratch("sliding_rough_z.npy");
  fs::remove(z);
  REQUIRE(run_coatfft("surface -o " + z.string() +
                      " --nx 64 --ny 64 --lx 0.5e-3 --ly 0.5e-3 --hurst 0.8 --rms-height 0.3e-6 "
                      "--short-cutoff 3e-5 --seed 3")
              .status == 0);
  const coatfft::Field topography = coatfft::io::read_npy(z);
  const fs::path gap = scratch("sliding_rough_gap.npy");
  coatfft::io::write_npy(gap, topography.maxCoeff() - topography);
  const std::string scene =
      "[grid]\nnx = 64\nny = 64\nlx = 0.5e-3\nly = 0.5e-3\nboundary = \"periodic\"\n"
      "[substrate]\nmaterial = \"steel\"\n[[coating]]\nmaterial = \"titanium_nitride\"\n"
      "thickness = 2e-5\n[contact]\nindenter = \"height_map\"\npath = \"" +
      gap.string() + "\"\nload = 5.0\nfriction = 0.3\n[stress]\ndepths = [2e-5]\n";
  const fs::path out = run_scene_ok(scene, "sliding_rough_periodic");
  const nlohmann::json s = read_summary(out);
  CHECK(s["converged"] == true);
  CHECK(s["friction_coupling"]["converged"] == true);
  CHECK(s["friction_coupling"]["solves"].get<int>() >= 2);
  CHECK(s["friction_coupling"]["pressure_shift"].get<double>() > 0.0);
  CHECK(s["total_load"].get<double>() == Approx(5.0).epsilon(1e-9));
  for (const char* name : {"ux.npy", "uy.npy"}) {
    const coatfft::Field u = coatfft::io::read_npy(out / name);
    CHECK(std::abs(u.mean()) < 1e-12 * u.abs().maxCoeff());
  }
  // The interface (2e-5 m) seen from the coating and from the substrate.
  const auto& layers = s["stress"]["layers"];
  REQUIRE(layers.size() == 2);
  CHECK(layers[0]["max_von_mises"]["z"].get<double>() <= 2e-5 * (1 + 1e-12));
  CHECK(layers[1]["max_von_mises"]["z"].get<double>() == Approx(2e-5));
}

TEST_CASE("a light rough periodic contact converges only on a solution", "[cli_periodic]") {
  // The surface and load at which the solver once stopped after one iteration with one cell in
  // contact, `converged`, while another cell overlapped by 1.4e-9 m. Now summary.json reports
  // the largest overlap of the converged solution, at the solver's accuracy (the property over
  // many rough gaps, against an independently recomputed gap: test_contact_complementarity.cpp).
  const fs::path z = scratch("light_rough_z.npy");
  fs::remove(z);
  REQUIRE(run_coatfft("surface -o " + z.string() +
                      " --nx 64 --ny 64 --lx 0.5e-3 --ly 0.5e-3 --hurst 0.8 --rms-height 0.2e-6 "
                      "--seed 1")
              .status == 0);
  const coatfft::Field topography = coatfft::io::read_npy(z);
  const fs::path gap = scratch("light_rough_gap.npy");
  coatfft::io::write_npy(gap, topography.maxCoeff() - topography);
  const std::string scene =
      "[grid]\nnx = 64\nny = 64\nlx = 0.5e-3\nly = 0.5e-3\nboundary = \"periodic\"\n"
      "[substrate]\nmaterial = \"steel\"\n[contact]\nindenter = \"height_map\"\npath = \"" +
      gap.string() + "\"\nload = 0.01\n";
  const fs::path out = scratch("light_rough_out");
  fs::remove_all(out);
  const auto run = run_coatfft("run " + write_scene(scene, "light_rough", "", "").string() +
                               " -o " + out.string());
  INFO(run.stderr_text);
  REQUIRE(run.status == 0);
  // A period has no edge: no "domain too small" warning.
  CHECK(run.stderr_text.find("domain") == std::string::npos);
  const nlohmann::json s = read_summary(out);
  CHECK(s["converged"] == true);
  CHECK(s["iterations"].get<int>() > 1);
  CHECK(s["contact_area"].get<double>() > 1.5 * (0.5e-3 / 64) * (0.5e-3 / 64));  // > one cell
  // 1e-10 (the tolerance) of a displacement below 1 um, plus rounding: far below the 1.4e-9 m.
  CHECK(s["max_penetration"].get<double>() <= 1e-15);
  CHECK(s["max_penetration"].get<double>() >= 0.0);
}

TEST_CASE("a periodic scene's stresses balance its mean pressure on every plane",
          "[cli_periodic]") {
  // On a periodic surface the mean of sigma_zz over any plane is minus the mean pressure
  // (equilibrium of the slab above it), and the means of the shear stresses are zero; a free
  // surface's window has no such balance. The in-plane surface displacements, periodic, have
  // zero mean.
  const fs::path out =
      run_scene_ok(kPeriodicHertz + "[stress]\ndepths = [2.5e-4, 1e-3]\n", "periodic_stress");
  const nlohmann::json s = read_summary(out);
  CHECK(s["stress"]["periodic"] == true);
  CHECK(s["stress"]["alpha"].is_null());
  const coatfft::Field ux = coatfft::io::read_npy(out / "ux.npy");
  CHECK(std::abs(ux.mean()) < 1e-12 * ux.abs().maxCoeff());
  REQUIRE(npy_shape(out / "stress.npy") == "(2, 6, 64, 64)");
  const std::vector<double> stress = npy_values(out / "stress.npy");
  const double mean_p = s["total_load"].get<double>() / (3e-3 * 3e-3);
  const std::size_t plane = 64 * 64;
  for (std::size_t d = 0; d < 2; ++d) {
    const auto mean = [&](int c) {
      double sum = 0.0;
      for (std::size_t n = 0; n < plane; ++n) sum += stress[(6 * d + c) * plane + n];
      return sum / plane;
    };
    CHECK(std::abs(mean(2) + mean_p) < 1e-12 * 1e9);  // sigma_zz; p0 = 1 GPa
    for (int c : {3, 4, 5}) CHECK(std::abs(mean(c)) < 1e-12 * 1e9);
  }
}

TEST_CASE("periodic scenes refuse what they do not support", "[cli_periodic]") {
  const BadCase cases[] = {
      {"periodic_spectral", "material = \"steel\"",
       "material = \"steel\"\n[method]\nname = \"frf-spectral\"", "free (non-periodic)"},
      {"periodic_odd", "nx = 64", "nx = 63", "even"},
      {"periodic_refine", "nx = 64\nny = 64", "refine = \"auto\"\ntolerance_total = 0.01",
       "refine"},
      {"periodic_stress_alpha", "a = 1.0e-3", "a = 1.0e-3\n[stress]\ndepths = [5e-4]\nalpha = 8",
       "alpha"},
      {"periodic_boundary", "boundary = \"periodic\"", "boundary = \"open\"", "boundary"},
      // The automatic choice's tolerance is a model of free surfaces; Python refuses it alike.
      {"periodic_tolerance", "material = \"steel\"",
       "material = \"steel\"\n[method]\ntolerance = 1e-3", "applies only to free boundaries"},
  };
  for (const BadCase& c : cases) check_refused(kPeriodicHertz, c);
}

TEST_CASE("a periodic scene leaves out a coating far thinner than a cell, or names it",
          "[cli_periodic]") {
  // A picometre film (and a 1e-300 m one) made the periodic kernel sum the FRF to k ~ 1/h and
  // refuse in its own terms. "auto" leaves the film out where the body reduction bounds its
  // effect (the free path's rule): the displacement is the bare steel's to the bound, 1e-4 at
  // most, and the summary's warnings say so. A named method names the coating.
  std::string bare = kPeriodicHertz;
  const nlohmann::json steel = read_summary(run_scene_ok(bare, "thin_bare"));
  for (const char* thickness : {"1e-12", "1e-300"}) {
    INFO(thickness);
    const std::string film =
        bare + "[[coating]]\nmaterial = \"alumina\"\nthickness = " + std::string(thickness) + "\n";
    const nlohmann::json s = read_summary(run_scene_ok(film, "thin_film"));
    CHECK(s["method_requested"] == "auto");
    CHECK(s["uz_center"].get<double>() == Approx(steel["uz_center"].get<double>()).epsilon(1e-4));
    REQUIRE(s["warnings"].size() == 1);
    CHECK(s["warnings"][0].get<std::string>().rfind("[method] auto: substrate", 0) == 0);
    check_refused(film + "[method]\nname = \"frf-split\"\n",
                  {"thin_named", "[method]", "[method]",
                   (std::string("[[coating]] 1 thickness = ") + thickness).c_str()});
  }
}
