// The lines `coatfft run` prints (scene/run_highlights.hpp), read back as a person reads them
// and checked against Hertz's closed forms (Johnson 1985, sections 3.4 and 4.2.1): a sphere on a
// half-space, then on a coated flat, whose contact lies between the bare substrate's and the
// bare coating's. Small grids, so that each case runs in a fraction of a second.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "scene/run_highlights.hpp"
#include "scene/scene_run.hpp"
#include "stress/stress_invariants.hpp"
#include "tests/test_materials.hpp"
#include "validation/hertz_contact.hpp"
#include "validation/hertz_stress.hpp"

namespace fs = std::filesystem;
using coatfft::scene::run_highlights;

namespace {

// A rigid sphere R = 10 mm under 10 N (Hertz on steel: a = 68.8 um, p0 = 1.01 GPa) on 41 x 41
// cells over 0.3 mm (dx = 7.3 um = a / 9.4; the origin a cell centre), with the section y = 0
// down to 40 um in 8 rows of 5 um.
const double kRadius = 0.01, kLoad = 10.0, kCells = 41, kSide = 0.3e-3, kRow = 5e-6;

std::string stressed_sphere_scene(const std::string& coating) {
  return R"([grid]
nx = 41
ny = 41
lx = 0.3e-3
ly = 0.3e-3
[substrate]
material = "steel"
)" + coating +
         R"(
[contact]
indenter = "sphere"
radius = 0.01
load = 10.0
[method]
name = "frf-split"
[stress]
section = "xz"
depth_max = 40e-6
nz = 8
alpha = 4
)";
}

// The run of a scene's text, through a file of its own (removed again).
coatfft::scene::SceneRun run_text(const std::string& text, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("coatfft_highlights_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.toml") << text;
  coatfft::scene::SceneRun run = coatfft::scene::run_scene(dir / "scene.toml");
  fs::remove_all(dir);
  return run;
}

// The line that starts with `start`; fails the test when there is none.
std::string line_starting(const std::vector<std::string>& lines, const std::string& start) {
  for (const std::string& line : lines)
    if (line.rfind(start, 0) == 0) return line;
  FAIL("no line starts with \"" << start << "\"");
  return {};
}

// The quantity written right after `label` in `line` ("41.2 µm", "1.63 GPa", "0"), in SI units,
// read as a person reads it.
double quantity_after(const std::string& line, const std::string& label) {
  static const std::map<std::string, double> units = {{"nm", 1e-9}, {"µm", 1e-6}, {"mm", 1e-3},
                                                      {"m", 1.0},   {"Pa", 1.0},  {"kPa", 1e3},
                                                      {"MPa", 1e6}, {"GPa", 1e9}, {"", 1.0}};
  const std::size_t at = line.find(label);
  REQUIRE(at != std::string::npos);
  std::smatch m;
  const std::string rest = line.substr(at + label.size());
  REQUIRE(
      std::regex_search(rest, m, std::regex(R"(^([-0-9.e+]+)( (nm|µm|mm|m|kPa|MPa|GPa|Pa)\b)?)")));
  return std::stod(m[1].str()) * units.at(m[3].str());
}

// Three significant digits round to half a unit of the third: at most 5e-3 of the value.
constexpr double kPrinted = 5e-3;

// The quantity of the line that starts with `label`, checked strictly between Hertz's values on
// the bare substrate and the bare top coating, which the line prints beside it.
double check_between(const std::vector<std::string>& lines, const std::string& label,
                     double substrate, double coating) {
  const std::string line = line_starting(lines, label);
  const double value = quantity_after(line, label);
  CHECK(value > std::min(substrate, coating));
  CHECK(value < std::max(substrate, coating));
  CHECK(quantity_after(line, "(Hertz: ") == Approx(substrate).epsilon(kPrinted));
  CHECK(quantity_after(line, "substrate, ") == Approx(coating).epsilon(kPrinted));
  return value;
}

}  // namespace

TEST_CASE("run highlights: a sphere on a half-space prints Hertz's radius, pressure and stress",
          "[highlights]") {
  const auto run = run_text(stressed_sphere_scene(""), "half_space");
  const std::vector<std::string> lines = run_highlights(run.summary);
  INFO(run.summary.dump(1));
  REQUIRE(lines.size() == 3);  // contact radius, peak pressure, von Mises: no interface
  const auto hertz = coatfft::hertz_sphere_for_load(kLoad, kRadius, steel.plane_strain_modulus());
  const double a = hertz.contact_radius, p0 = hertz.max_pressure, dx = kSide / kCells;

  // The contact is a set of whole cells, its edge known to half a cell: sqrt(area / pi) within
  // dx / 2 of a, plus the printed rounding. Measured: 70.7 um against 68.8 um (0.26 dx).
  const std::string radius = line_starting(lines, "contact radius ");
  CHECK(std::abs(quantity_after(radius, "contact radius ") - a) <= 0.5 * dx + kPrinted * a);
  CHECK(quantity_after(radius, "(Hertz: ") == Approx(a).epsilon(kPrinted));

  // The centre cell's pressure: the solver's discretisation is O((dx/a)^2) (the example
  // sphere_contact.toml: 3.6e-4 at dx = a / 23.7); bound (dx/a)^2 = 1.1e-2 here, plus the
  // printed rounding. Measured: 1.0105 GPa against 1.0101 GPa (4.3e-4).
  const std::string peak = line_starting(lines, "peak pressure ");
  CHECK(std::abs(quantity_after(peak, "peak pressure ") - p0) <=
        ((dx / a) * (dx / a) + kPrinted) * p0);
  CHECK(quantity_after(peak, "(Hertz: ") == Approx(p0).epsilon(kPrinted));

  // Hertz's largest von Mises stress on the axis (Huber 1904; Johnson 1985, section 3.4: 0.62 p0
  // at 0.48 a for nu = 0.3), found on a fine grid of depths from the closed form. The run's is
  // the largest over the section's rows (every 5 um = a / 14) under the cell-wise pressure:
  // within the pressure's discretisation and a row of it. Measured: 625 MPa at 35 um against
  // 626 MPa at 33.1 um (1.7e-3 p0).
  double vm = 0.0, z_vm = 0.0;
  for (int k = 1; k <= 2000; ++k) {
    const double z = a * k / 2000.0;
    const auto s = coatfft::hertz_sliding_stress(0.0, 0.0, z, p0, a, steel.poisson_ratio(), 0.0);
    const double v = coatfft::von_mises({s.xx, s.yy, s.zz, s.yz, s.xz, s.xy});
    if (v > vm) {
      vm = v;
      z_vm = z;
    }
  }
  const std::string mises = line_starting(lines, "largest von Mises stress ");
  CHECK(std::abs(quantity_after(mises, "stress ") - vm) <= ((dx / a) * (dx / a) + kPrinted) * p0);
  CHECK(quantity_after(mises, "x = ") == 0.0);
  CHECK(std::abs(quantity_after(mises, "depth ") - z_vm) <= kRow);
  CHECK(mises.find("(in ") == std::string::npos);  // one medium: nothing to name
}

TEST_CASE("run highlights: a stiff coating raises the peak pressure and shrinks the contact",
          "[highlights]") {
  // TiN (E* = 427 GPa) 20 um thick on steel (231 GPa): h = 0.3 a, the contact in between.
  const double h = 20e-6;
  const auto run = run_text(stressed_sphere_scene(R"([[coating]]
material = "titanium_nitride"
thickness = 20e-6
interface = "bonded")"),
                            "coated");
  const std::vector<std::string> lines = run_highlights(run.summary);
  INFO(run.summary.dump(1));
  REQUIRE(lines.size() == 4);  // contact radius, peak pressure, von Mises, the interface's shear
  const auto bare_steel =
      coatfft::hertz_sphere_for_load(kLoad, kRadius, steel.plane_strain_modulus());
  const auto bare_tin = coatfft::hertz_sphere_for_load(kLoad, kRadius, tin.plane_strain_modulus());

  // Between the bare half-spaces (Hertz on TiN: a = 56.0 um, p0 = 1.52 GPa; on steel 68.8 um,
  // 1.01 GPa), each printed beside the run's. Measured: 64.1 um and 1.08 GPa. The margins,
  // 4.7 um = 0.64 dx to steel's radius and 0.069 GPa = 6.8 % to its pressure, exceed the
  // discretisation's bounds of the case above (dx / 2, 1.1e-2 p0), so the cell-wise contact
  // cannot cross a bound by discretisation.
  const double a =
      check_between(lines, "contact radius ", bare_steel.contact_radius, bare_tin.contact_radius);
  check_between(lines, "peak pressure ", bare_steel.max_pressure, bare_tin.max_pressure);

  // The largest von Mises stress of the body, found here in the arrays the run computed (not in
  // its summary): the section's rows (nz, nx), at depths 5 um k, k = 1..8, in the medium below an
  // interface depth (at_interface's default), and the interface's planes (2, ny, nx), the coating
  // above it (side 0) and the substrate below. Measured: 818 MPa at the origin on the interface,
  // in the coating (the substrate's largest is 684 MPa at 30 um).
  const coatfft::scene::StressRun& stress = *run.stress;
  double largest = 0.0, depth = 0.0;
  bool in_coating = false;
  for (std::size_t n = 0; n < stress.section_von_mises.size(); ++n)
    if (stress.section_von_mises[n] > largest) {
      largest = stress.section_von_mises[n];
      depth = kRow * static_cast<double>(n / std::size_t(kCells) + 1);
      in_coating = depth < h * (1 - 1e-9);
    }
  const std::size_t plane = std::size_t(kCells * kCells);
  for (std::size_t n = 0; n < stress.interfaces_von_mises.size(); ++n)
    if (stress.interfaces_von_mises[n] > largest) {
      largest = stress.interfaces_von_mises[n];
      depth = h;
      in_coating = n < plane;
    }
  const std::string mises = line_starting(lines, "largest von Mises stress ");
  CHECK(quantity_after(mises, "stress ") == Approx(largest).epsilon(kPrinted));
  CHECK(quantity_after(mises, "depth ") == Approx(depth).epsilon(kPrinted));
  CHECK((mises.find("(in the coating") != std::string::npos) == in_coating);
  CHECK((mises.find("(in the substrate") != std::string::npos) == !in_coating);
  CHECK((mises.find(", at the interface)") != std::string::npos) ==
        (std::abs(depth - h) <= 1e-9 * h));
  // The interface's shear stress, at its depth, inside the contact.
  const std::string shear = line_starting(lines, "largest interface shear stress ");
  CHECK(quantity_after(shear, "interface at depth ") == Approx(h).epsilon(kPrinted));
  CHECK(quantity_after(shear, "shear stress ") > 0.0);
  CHECK(quantity_after(shear, "at r = ") < a);
}

TEST_CASE("run highlights: only the lines that apply, in readable units", "[highlights]") {
  // A known load without [stress]: nothing to tell.
  CHECK(run_highlights({{"total_load", 1.0}, {"uz_max", 1e-6}}).empty());
  // A contact without Hertz's values (a cylinder, or an approach): no comparison; a contact
  // that is not round gives the radius of the disk of its area.
  const nlohmann::json cylinder = {{"contact_area", 3.0e-8},
                                   {"equivalent_radius", 9.772e-5},
                                   {"contact_radius", nullptr},
                                   {"max_pressure", 9.996e8}};
  CHECK(run_highlights(cylinder) ==
        std::vector<std::string>{"equivalent contact radius 97.7 µm (of the disk of the contact's "
                                 "area; the contact is not round)",
                                 "peak pressure 1 GPa"});
  // Stresses: the largest von Mises stress off the interface, its medium named without "at the
  // interface", a cell centre's rounding (1e-22 m) printed as 0; the interface's shear stress at
  // r = hypot(x, y).
  const nlohmann::json coating = {{"thickness", 2e-5}};
  const nlohmann::json mises = {
      {"value", 6.84e8}, {"x", 1e-22}, {"y", 0.0}, {"z", 3e-5}, {"medium", "substrate"}};
  const nlohmann::json shear = {{"value", 2.46e8}, {"x", -3e-5}, {"y", 4e-5}};
  const nlohmann::json stressed = {
      {"nx", 41},
      {"ny", 41},
      {"lx", 0.3e-3},
      {"ly", 0.3e-3},
      {"body", {{"coatings", nlohmann::json::array({coating})}}},
      {"stress",
       {{"max_von_mises", mises},
        {"interfaces", nlohmann::json::array({{{"depth", 2e-5}, {"max_shear", shear}}})}}}};
  CHECK(run_highlights(stressed) ==
        std::vector<std::string>{
            "largest von Mises stress 684 MPa at x = 0, y = 0, depth 30 µm (in the substrate)",
            "largest interface shear stress 246 MPa at r = 50 µm (interface at depth 20 µm)"});
  // A sweep's contact keys are its largest load's, and the lines say so first.
  nlohmann::json sweep = cylinder;
  sweep["sweep"] = nlohmann::json::array();
  sweep["load"] = 40.0;
  CHECK(run_highlights(sweep).front() == "at the sweep's largest load, 40 N:");
  // A value that is not finite leaves its line out rather than printing it.
  nlohmann::json broken = cylinder;
  broken["max_pressure"] = std::nan("");
  CHECK(run_highlights(broken).size() == 1);
}
