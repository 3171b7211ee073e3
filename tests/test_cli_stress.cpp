// [stress], [shear] and [contact] friction in scenes: the files and summary keys a run writes,
// their shapes and their agreement with the library called directly, the tangential tractions
// entering by linearity, and the refusals (one line, exit 2, no output).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "io/npy.hpp"
#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

const std::string kStress = std::string(kGoodScene) + R"([stress]
depths = [2.5e-4, 5.0e-4]
section = "xz"
depth_max = 1.0e-3
nz = 4
alpha = 4
)";

const std::string kCoatedStress = R"([grid]
nx = 24
ny = 20
lx = 3.0e-3
ly = 2.5e-3
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 2e-4
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
sampling = "cell_average"
[method]
name = "frf-split"
[stress]
depths = [1e-4, 2e-4]
alpha = 4
)";

}  // namespace

TEST_CASE("[stress] writes the stress files with their shapes and summary keys", "[cli_stress]") {
  const fs::path out = run_scene_ok(kStress, "stress_files");
  CHECK(npy_shape(out / "stress.npy") == "(2, 6, 33, 33)");
  CHECK(npy_shape(out / "von_mises.npy") == "(2, 33, 33)");
  CHECK(npy_shape(out / "stress_section.npy") == "(4, 6, 33)");
  CHECK(npy_shape(out / "von_mises_section.npy") == "(4, 33)");
  // A homogeneous body: the in-plane surface displacements too (Cerruti's closed forms).
  CHECK(npy_shape(out / "ux.npy") == "(33, 33)");
  CHECK(npy_shape(out / "uy.npy") == "(33, 33)");
  // u_x under the pressure points to the load's centre: negative at x > 0, zero on the axis.
  const std::vector<double> ux = npy_values(out / "ux.npy");
  CHECK(ux[16 * 33 + 24] < 0.0);
  CHECK(std::abs(ux[16 * 33 + 16]) < 1e-6 * std::abs(ux[16 * 33 + 24]));
  const nlohmann::json s = read_summary(out)["stress"];
  for (const char* key : {"max_von_mises", "max_principal_tensile"})
    for (const char* k : {"value", "x", "y", "z"}) CHECK(s[key].contains(k));
  CHECK(s["interfaces"].empty());  // a homogeneous body
  CHECK(s["planes"] == 6);
  // One medium, which holds every plane: its maxima are the body's.
  REQUIRE(s["layers"].size() == 1);
  CHECK(s["layers"][0]["medium"] == "substrate");
  for (const char* key : {"max_von_mises", "max_principal_tensile", "max_tresca"}) {
    nlohmann::json overall = s[key];
    CHECK(overall["medium"] == "substrate");
    overall.erase("medium");
    CHECK(s["layers"][0][key] == overall);
  }

  // The section row at z = 2.5e-4 (k = 1 of 4) is the row j = 16 (y = 0) of the first plane.
  const std::vector<double> plane = npy_values(out / "stress.npy");
  const std::vector<double> section = npy_values(out / "stress_section.npy");
  for (int c = 0; c < 6; ++c)
    for (int i = 0; i < 33; ++i) CHECK(section[c * 33 + i] == plane[(c * 33 + 16) * 33 + i]);
  // sigma_zz on the axis: Johnson's (1985) eq. 3.45 within the coarse grid's error (dx = a/11).
  const double szz = plane[(2 * 33 + 16) * 33 + 16];
  CHECK(szz == Approx(-1e9 / (1 + 0.0625)).epsilon(5e-3));
  // The largest von Mises stress is the largest entry of the von Mises files.
  double vm = 0;
  for (const auto* f : {"von_mises.npy", "von_mises_section.npy"})
    for (double v : npy_values(out / f)) vm = std::max(vm, v);
  CHECK(s["max_von_mises"]["value"].get<double>() == vm);
}

TEST_CASE("[stress] on a coated body reports the interface's largest shear", "[cli_stress]") {
  const fs::path out = run_scene_ok(kCoatedStress, "stress_coated");
  // The in-plane surface displacements of the layered body
  // (convolution/kernels/traction_kernels.hpp).
  CHECK(npy_shape(out / "ux.npy") == "(20, 24)");
  CHECK(npy_shape(out / "uy.npy") == "(20, 24)");
  const nlohmann::json s = read_summary(out)["stress"];
  REQUIRE(s["interfaces"].size() == 1);
  CHECK(s["interfaces"][0]["depth"].get<double>() == Approx(2e-4));
  // The interface plane is the second requested plane; its largest |shear| is the same value.
  const std::vector<double> plane = npy_values(out / "stress.npy");
  double shear = 0;
  const int n = 24 * 20;
  for (int c = 0; c < n; ++c)
    shear = std::max(shear, std::hypot(plane[(6 + 4) * n + c], plane[(6 + 3) * n + c]));
  CHECK(s["interfaces"][0]["max_shear"]["value"].get<double>() == Approx(shear).epsilon(1e-12));
  // The interface plane asked for lies below it, in the substrate, whose maximum is at least
  // that plane's; the coating's maxima include the same interface seen from above.
  REQUIRE(s["layers"].size() == 2);
  CHECK(s["layers"][0]["medium"] == "coating 1");
  CHECK(s["layers"][1]["medium"] == "substrate");
  const std::vector<double> vm = npy_values(out / "von_mises.npy");
  const double interface_vm = *std::max_element(vm.begin() + n, vm.begin() + 2 * n);
  CHECK(s["layers"][1]["max_von_mises"]["value"].get<double>() >= interface_vm);
  CHECK(s["planes"] == s["depths"].size() + 2);
}

TEST_CASE("[output] fields chooses the stress files", "[cli_stress]") {
  const fs::path out =
      run_scene_ok(kStress + "[output]\nfields = [\"summary\", \"von_mises\"]\n", "stress_fields");
  CHECK(fs::exists(out / "von_mises.npy"));
  CHECK(fs::exists(out / "summary.json"));
  for (const char* absent : {"stress.npy", "stress_section.npy", "von_mises_section.npy", "uz.npy",
                             "pressure.npy", "displacement.csv"})
    CHECK_FALSE(fs::exists(out / absent));
  // The summary holds the maxima whichever files are written, the same as a run that writes
  // everything; the files written hold the same values; the in-plane displacements, not asked
  // for, are not computed (no ux.npy, and no warning that they are missing).
  const fs::path full = run_scene_ok(kStress, "stress_fields_full");
  const nlohmann::json s = read_summary(out), all = read_summary(full);
  CHECK(s["stress"]["layers"].size() == 1);
  for (const char* key : {"max_von_mises", "max_principal_tensile", "max_tresca"})
    CHECK(s["stress"][key] == all["stress"][key]);
  CHECK(npy_values(out / "von_mises.npy") == npy_values(full / "von_mises.npy"));
  CHECK(fs::exists(full / "ux.npy"));
  CHECK_FALSE(fs::exists(out / "ux.npy"));
  CHECK(s["warnings"].dump().find("ux.npy") == std::string::npos);
  // "ux" alone: ux.npy, the full run's, and no uy.npy.
  const fs::path ux = run_scene_ok(kStress + "[output]\nfields = [\"ux\"]\n", "stress_fields_ux");
  CHECK(npy_values(ux / "ux.npy") == npy_values(full / "ux.npy"));
  CHECK_FALSE(fs::exists(ux / "uy.npy"));
  CHECK_FALSE(fs::exists(ux / "stress.npy"));
  const std::string no_section = kStress + "[output]\nfields = [\"stress_section\"]\n";
  check_refused(no_section, {"fields_section", "section = \"xz\"\ndepth_max = 1.0e-3\nnz = 4\n", "",
                             "give [stress] section"});
  check_refused(std::string(kGoodScene) + "[output]\nfields = [\"stress\"]\n",
                {"fields_no_stress", "", "", "give [stress] depths"});
}

TEST_CASE("[stress] on a frictionless interface writes no ux.npy and says why", "[cli_stress]") {
  std::string scene = kCoatedStress;
  scene.replace(scene.find("thickness = 2e-4"), 16,
                "thickness = 2e-4\ninterface = \"frictionless\"");
  const fs::path out = run_scene_ok(scene, "stress_frictionless");
  CHECK(fs::exists(out / "stress.npy"));
  CHECK_FALSE(fs::exists(out / "ux.npy"));
  CHECK_FALSE(fs::exists(out / "uy.npy"));
  bool said = false;
  const nlohmann::json summary = read_summary(out);
  for (const auto& w : summary["warnings"])
    said = said || w.get<std::string>().find("frictionless") != std::string::npos;
  CHECK(said);
}

TEST_CASE("[shear] proportional adds mu times the unit-traction field", "[cli_stress]") {
  // Linearity: the run with [shear] mu = 0.3 minus the run without equals 0.3 times (the run with
  // mu = 1 minus the run without).
  const std::string base = kStress;
  const auto shear = [](const char* mu) {
    return std::string("[shear]\nkind = \"proportional\"\nmu = ") + mu + "\ndirection = \"y\"\n";
  };
  const std::vector<double> s0 = npy_values(run_scene_ok(base, "shear0") / "stress.npy");
  const std::vector<double> s3 =
      npy_values(run_scene_ok(base + shear("0.3"), "shear3") / "stress.npy");
  const std::vector<double> s1 =
      npy_values(run_scene_ok(base + shear("1.0"), "shear1") / "stress.npy");
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < s0.size(); ++i) {
    worst = std::max(worst, std::abs((s3[i] - s0[i]) - 0.3 * (s1[i] - s0[i])));
    scale = std::max(scale, std::abs(s1[i] - s0[i]));
  }
  CHECK(scale > 1e7);  // the traction does change the stresses
  // Rounding of stresses of the size of p0 = 1e9 Pa in three runs.
  CHECK(worst < 1e-12 * 1e9);
  CHECK(read_summary(scratch("shear3_out"))["stress"]["tangential"] == true);
  // uz holds the tractions' share too (homogeneous body), linear as well: 0.3 of mu = 1's.
  const auto uz = [](const char* name) { return npy_values(scratch(name) / "uz.npy"); };
  const std::vector<double> z0 = uz("shear0_out"), z3 = uz("shear3_out"), z1 = uz("shear1_out");
  double dz = 0, zmax = 0;
  for (std::size_t i = 0; i < z0.size(); ++i) {
    dz = std::max(dz, std::abs((z3[i] - z0[i]) - 0.3 * (z1[i] - z0[i])));
    zmax = std::max(zmax, std::abs(z0[i]));
  }
  CHECK(dz < 1e-12 * zmax);
  CHECK(read_summary(scratch("shear1_out"))["tangential_uz"].get<double>() > 0.01);
}

TEST_CASE("[shear] file equals proportional for the same tractions", "[cli_stress]") {
  const fs::path prop =
      run_scene_ok(kStress + "[shear]\nkind = \"proportional\"\nmu = 0.25\n", "shear_p");
  // q_x = 0.25 p written as a file.
  const fs::path p_file = scratch("shear_qx.npy");
  coatfft::io::write_npy(p_file, 0.25 * coatfft::io::read_npy(prop / "pressure.npy"));
  const fs::path file = run_scene_ok(
      kStress + "[shear]\nkind = \"file\"\npath_x = \"" + p_file.string() + "\"\n", "shear_f");
  CHECK(npy_values(prop / "stress.npy") == npy_values(file / "stress.npy"));
}

TEST_CASE("[stress], [shear] and friction refuse bad scenes with one line", "[cli_stress]") {
  const std::string with_shear = kStress + "[shear]\nkind = \"proportional\"\nmu = 0.2\n";
  const BadCase cases[] = {
      {"stress_zero_depth", "depths = [2.5e-4, 5.0e-4]", "depths = [0.0]", "must be > 0"},
      {"stress_shallow", "depths = [2.5e-4, 5.0e-4]", "depths = [1e-7]", "too shallow"},
      {"stress_nan", "depths = [2.5e-4, 5.0e-4]", "depths = [nan]", "finite"},
      {"stress_alpha", "alpha = 4", "alpha = 1", "alpha"},
      {"stress_alpha_big", "alpha = 4", "alpha = 33", "alpha"},
      {"stress_section", "section = \"xz\"", "section = \"yz\"", "section"},
      {"stress_nz", "nz = 4", "nz = 0", "nz"},
      {"stress_depth_max", "depth_max = 1.0e-3", "depth_max = -1.0", "depth_max"},
      {"stress_unknown", "alpha = 4", "alpha = 4\nplanes = 3", "unknown key"},
      {"stress_at_interface", "alpha = 4", "alpha = 4\nat_interface = \"middle\"", "at_interface"},
  };
  for (const BadCase& c : cases) check_refused(kStress, c);
  const BadCase shear_cases[] = {
      {"shear_mu", "mu = 0.2", "mu = -1", "mu"},
      {"shear_kind", "kind = \"proportional\"", "kind = \"random\"", "kind"},
      {"shear_direction", "mu = 0.2", "mu = 0.2\ndirection = \"z\"", "direction"},
      {"shear_no_path", "kind = \"proportional\"\nmu = 0.2", "kind = \"file\"", "path_x"},
      {"shear_missing_file", "kind = \"proportional\"\nmu = 0.2",
       "kind = \"file\"\npath_x = \"nothing_here.npy\"", "nothing_here.npy"},
  };
  for (const BadCase& c : shear_cases) check_refused(with_shear, c);
  // [shear] with a frictionless interface; on a coating so thin against the domain that its
  // traction kernels would need about 1e11 FRF evaluations; friction on a frictionless interface.
  check_refused(kCoatedStress + "[shear]\nkind = \"proportional\"\nmu = 0.2\n",
                {"shear_frictionless", "thickness = 2e-4",
                 "thickness = 2e-4\ninterface = \"frictionless\"", "frictionless"});
  check_refused(kCoatedStress.substr(0, kCoatedStress.find("[stress]")) +
                    "[shear]\nkind = \"proportional\"\nmu = 0.2\n",
                {"shear_thin_coating", "thickness = 2e-4", "thickness = 1e-7", "so thin"});
  check_refused(std::string(kSmallContactScene) +
                    "friction = 0.2\n[[coating]]\nmaterial = \"titanium_nitride\"\nthickness = "
                    "2e-4\ninterface = \"frictionless\"\n",
                {"friction_frictionless", "", "", "frictionless"});
}

TEST_CASE("[shear] without [stress] writes the surface displacements of a coated body",
          "[cli_stress]") {
  // The coated scene without its [stress] section, with and without a traction q_y = 0.3 p.
  std::string base = kCoatedStress;
  base = base.substr(0, base.find("[stress]"));
  const fs::path plain = run_scene_ok(base, "shear_coated0");
  const fs::path sheared = run_scene_ok(
      base + "[shear]\nkind = \"proportional\"\nmu = 0.3\ndirection = \"y\"\n", "shear_coated");
  CHECK_FALSE(fs::exists(plain / "ux.npy"));  // neither tractions nor stresses
  CHECK(npy_shape(sheared / "ux.npy") == "(20, 24)");
  CHECK_FALSE(fs::exists(sheared / "stress.npy"));
  // Along +y the surface is dragged along +y: u_y > 0 at the centre; u_z changes by the
  // coupling, which is odd in y (zero on average over the grid's symmetric rows).
  const std::vector<double> uy = npy_values(sheared / "uy.npy");
  const std::vector<double> z0 = npy_values(plain / "uz.npy");
  const std::vector<double> z1 = npy_values(sheared / "uz.npy");
  CHECK(uy[10 * 24 + 12] > 0.0);
  double change = 0, total = 0;
  for (std::size_t i = 0; i < z0.size(); ++i) {
    change = std::max(change, std::abs(z1[i] - z0[i]));
    total += z1[i] - z0[i];
  }
  CHECK(change > 1e-3 * *std::max_element(z0.begin(), z0.end()));
  CHECK(std::abs(total) < 1e-9 * change * z0.size());
  CHECK(read_summary(sheared)["tangential_uz"].get<double>() > 0.0);
}

TEST_CASE("[contact] friction iterates the normal-tangential coupling", "[cli_stress]") {
  const fs::path out =
      run_scene_ok(std::string(kSmallContactScene) + "friction = 0.3\n", "sliding");
  const nlohmann::json s = read_summary(out);
  REQUIRE(s.contains("friction_coupling"));
  const nlohmann::json& c = s["friction_coupling"];
  CHECK(c["converged"] == true);
  CHECK(c["solves"].get<int>() >= 3);
  CHECK(c["pressure_change"].get<double>() <= 1e-9);
  // Steel on a rigid sphere, mu = 0.3: the pressure moves by a few per cent of its peak (of the
  // order of beta mu, beta = (1 - 2 nu)/(2 (1 - nu)) = 0.29; Johnson 1985, section 7.2).
  CHECK(c["pressure_shift"].get<double>() > 1e-3);
  CHECK(c["pressure_shift"].get<double>() < 0.2);
  CHECK(c["centroid_shift"].get<double>() < 0.0);  // towards the trailing side
  CHECK(npy_shape(out / "ux.npy") == "(32, 32)");
  // Two bodies of one material: the tractions displace both surfaces alike, no coupling (the
  // body's K_zx less the indenter's is exactly 0): one more solve, the same pressure.
  const fs::path same = run_scene_ok(
      std::string(kSmallContactScene) + "friction = 0.3\nindenter_material = \"steel\"\n",
      "sliding_same");
  const nlohmann::json t = read_summary(same)["friction_coupling"];
  CHECK(t["solves"] == 2);
  CHECK(t["pressure_shift"].get<double>() == 0.0);
}

TEST_CASE("[stress] a section row on a running-sum interface lies on the at_interface side",
          "[cli_stress][interface]") {
  // Coatings of 10 um and 20 um: the interface is at 10e-6 + 20e-6 = 3.0000000000000004e-5 and
  // the section's first row at depth_max 1/2 = 3e-5, one ulp above it. The row is the interface
  // (LayerStack::locate): the row y = 0 of the plane at the exact interface depth, same side.
  const std::string scene = R"([grid]
nx = 24
ny = 20
lx = 0.12e-3
ly = 0.1e-3
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 10e-6
[[coating]]
E = 50e9
nu = 0.3
thickness = 20e-6
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 0.04e-3
sampling = "cell_average"
[method]
name = "frf-split"
[stress]
depths = [3.0000000000000004e-5]
section = "xz"
depth_max = 6e-5
nz = 2
alpha = 4
)";
  const std::string side_line = "at_interface = \"above\"\n";
  const fs::path below = run_scene_ok(scene, "stress_row_below");
  const fs::path above = run_scene_ok(scene + side_line, "stress_row_above");
  const int nx = 24, ny = 20, j = (ny - 1) / 2;  // Grid::centre_j, the section's row
  std::vector<double> row[2], plane[2];
  for (int b = 0; b < 2; ++b) {
    row[b] = npy_values((b ? below : above) / "stress_section.npy");
    plane[b] = npy_values((b ? below : above) / "stress.npy");
  }
  double jump = 0;
  for (int b = 0; b < 2; ++b)
    for (int c = 0; c < 6; ++c)
      for (int i = 0; i < nx; ++i) {
        // The fields are the interface's; the alias cut-offs differ by an ulp: 1e-12 of p0.
        CHECK(std::abs(row[b][c * nx + i] - plane[b][(c * ny + j) * nx + i]) < 1e-3);
        jump = std::max(jump, std::abs(row[1][c * nx + i] - row[0][c * nx + i]));
      }
  CHECK(jump > 3e7);  // the sides differ: sigma_xx jumps across the interface, 6.7 % of p0
  CHECK(read_summary(below)["stress"]["at_interface"] == "below");
}

namespace {

// A coating of thickness 2e-4 m on steel (16 x 14 cells over 2 x 1.75 mm) under a Hertz
// pressure (a = 0.6 mm) with the planes 2e-4 (the interface, below) and 3e-4 m, and the section's
// rows at 2e-4 and 4e-4 m: every plane asked for is in the substrate. `extra` adds to it.
std::string interface_scene(const std::string& coating_keys, const std::string& extra) {
  return "[substrate]\nmaterial = \"steel\"\n[[coating]]\nthickness = 2e-4\n" + coating_keys + R"(
[grid]
nx = 16
ny = 14
lx = 2.0e-3
ly = 1.75e-3
[method]
name = "frf-split"
[pressure]
kind = "hertz"
sampling = "cell_average"
a = 0.6e-3
p0 = 1.0e9
[stress]
depths = [2e-4, 3e-4]
section = "xz"
depth_max = 4e-4
nz = 2
alpha = 2
)" + extra;
}

// Von Mises, the largest principal stress and Tresca's shear of (xx, yy, zz, yz, xz, xy) by the
// closed form of a symmetric 3 x 3 matrix's eigenvalues (Smith 1961), not the program's
// iterative solver.
std::array<double, 3> invariants(const std::array<double, 6>& s) {
  const double q = (s[0] + s[1] + s[2]) / 3;
  const double off = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  const double p = std::sqrt(
      ((s[0] - q) * (s[0] - q) + (s[1] - q) * (s[1] - q) + (s[2] - q) * (s[2] - q) + 2 * off) / 6);
  double e1 = q, e3 = q;
  if (p > 0) {
    const double a = (s[0] - q) / p, b = (s[1] - q) / p, c = (s[2] - q) / p;
    const double d = s[3] / p, e = s[4] / p, f = s[5] / p;  // yz, xz, xy
    const double det = a * (b * c - d * d) - f * (f * c - d * e) + e * (f * d - b * e);
    const double phi = std::acos(std::clamp(det / 2, -1.0, 1.0)) / 3;
    e1 = q + 2 * p * std::cos(phi);
    e3 = q + 2 * p * std::cos(phi + 2 * std::numbers::pi / 3);
  }
  const double vm = std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                                     (s[2] - s[0]) * (s[2] - s[0])) +
                              3 * off);
  return {vm, e1, 0.5 * (e1 - e3)};
}

// A point of a written plane: where it is, its medium (0: the coating) and its invariants.
struct WrittenPoint {
  double x, y, z;
  int medium;
  std::array<double, 3> value;
};

// Every point of the planes a run wrote: stress.npy, stress_section.npy (the row y = y_centre)
// and stress_interfaces.npy (the interface 2e-4 from above, the coating, and from below).
std::vector<WrittenPoint> written_points(const fs::path& out) {
  const int nx = 16, ny = 14, n = nx * ny;
  const coatfft::Grid grid(nx, ny, 2.0e-3, 1.75e-3);
  const double h = 2e-4;
  std::vector<WrittenPoint> points;
  const auto add = [&](const std::vector<double>& v, std::size_t first, std::size_t stride, int i,
                       int j, double z, int medium) {
    std::array<double, 6> s{};
    for (std::size_t c = 0; c < 6; ++c) s[c] = v[first + c * stride];
    points.push_back({grid.x(i), grid.y(j), z, medium, invariants(s)});
  };
  const std::vector<double> planes = npy_values(out / "stress.npy");
  const double depths[] = {h, 3e-4};  // both in the substrate (at_interface = "below")
  for (int p = 0; p < 2; ++p)
    for (int k = 0; k < n; ++k)
      add(planes, std::size_t(6 * p * n + k), n, k % nx, k / nx, depths[p], 1);
  const std::vector<double> section = npy_values(out / "stress_section.npy");
  for (int r = 0; r < 2; ++r)
    for (int i = 0; i < nx; ++i)
      add(section, std::size_t(6 * r * nx + i), nx, i, (ny - 1) / 2, h * (r + 1), 1);
  const std::vector<double> sides = npy_values(out / "stress_interfaces.npy");
  REQUIRE(sides.size() == std::size_t(2 * 6 * n));
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < n; ++k)
      add(sides, std::size_t(6 * side * n + k), n, k % nx, k / nx, h, side);
  return points;
}

}  // namespace

TEST_CASE("[stress] maxima are the media's, over the planes written, interfaces from both sides",
          "[cli_stress][interface]") {
  // A stiff and a soft coating, under pressure alone and sliding (q_x = 0.3 p).
  const std::string stiff = "material = \"titanium_nitride\"", soft = "E = 2e10\nnu = 0.3";
  const std::string sliding = "[shear]\nkind = \"proportional\"\nmu = 0.3\n";
  const std::pair<std::string, std::string> scenes[] = {
      {stiff, ""}, {stiff, sliding}, {soft, ""}, {soft, sliding}};
  const char* keys[] = {"max_von_mises", "max_principal_tensile", "max_tresca"};
  const char* media[] = {"coating 1", "substrate"};
  int index = 0;
  for (const auto& [coating, extra] : scenes) {
    INFO("scene " << index);
    const fs::path out =
        run_scene_ok(interface_scene(coating, extra), "stress_maxima" + std::to_string(index++));
    CHECK(npy_shape(out / "stress_interfaces.npy") == "(1, 2, 6, 14, 16)");
    CHECK(npy_shape(out / "von_mises_interfaces.npy") == "(1, 2, 14, 16)");
    const nlohmann::json s = read_summary(out)["stress"];
    REQUIRE(s["layers"].size() == 2);
    const std::vector<WrittenPoint> points = written_points(out);
    for (int q = 0; q < 3; ++q) {
      INFO(keys[q]);
      // The overall maximum is one of the media's, entry for entry.
      const nlohmann::json& overall = s[keys[q]];
      double largest = -INFINITY;
      for (int m = 0; m < 2; ++m) {
        const nlohmann::json& layer = s["layers"][m][keys[q]];
        largest = std::max(largest, layer["value"].get<double>());
        if (overall["medium"] == media[m])
          for (const char* k : {"value", "x", "y", "z"}) CHECK(overall[k] == layer[k]);
      }
      CHECK(overall["value"].get<double>() == largest);
      // Against the written arrays: the largest value over all their points and per medium, and
      // a written point where the summary says. The closed-form eigenvalues lose about
      // sqrt(eps) |s| to acos near a double root: 1e-6 of the largest stress covers them.
      const double tolerance = 1e-6 * s["max_von_mises"]["value"].get<double>();
      double all = -INFINITY, per[2] = {-INFINITY, -INFINITY};
      bool located = false;
      for (const WrittenPoint& w : points) {
        all = std::max(all, w.value[q]);
        per[w.medium] = std::max(per[w.medium], w.value[q]);
        located = located || (overall["medium"] == media[w.medium] && overall["z"] == w.z &&
                              overall["x"] == w.x && overall["y"] == w.y &&
                              std::abs(w.value[q] - overall["value"].get<double>()) <= tolerance);
      }
      CHECK(std::abs(overall["value"].get<double>() - all) <= tolerance);
      for (int m = 0; m < 2; ++m)
        CHECK(std::abs(s["layers"][m][keys[q]]["value"].get<double>() - per[m]) <= tolerance);
      CHECK(located);
    }
    // The von Mises files hold the very values the summary's maximum is of.
    double vm = -INFINITY;
    for (const char* f : {"von_mises.npy", "von_mises_section.npy", "von_mises_interfaces.npy"})
      for (double v : npy_values(out / f)) vm = std::max(vm, v);
    CHECK(s["max_von_mises"]["value"].get<double>() == vm);
    // The stiff coating carries the largest von Mises stress on its bottom face, a plane no
    // depth asked for: the interface seen from above.
    if (coating == stiff) CHECK(s["max_von_mises"]["medium"] == "coating 1");
  }
}
