// The hardness cap (ContactOptions::hardness; docs/contact.md, "Hardness"): the capped contact
// against its limits, and the plastic area and residual depth of a rough surface on bare steel,
// on 2 um of TiN on steel and on 2 um of a soft aluminium alloy against the load. Writes
// docs/validation/hardness.md.
//
// The references: a sphere's capped pressure is flat at H over a disk and elastic outside (the
// gap closed there); as H falls below the elastic peak p0 the load rests on ever more cells at H,
// A -> W / H (the fully plastic limit); a cycle's unloading is elastic, so the depth after the
// peak is the peak's and the unloaded contact is the elastic contact of the dented surface. The
// box-constrained problem itself is checked against an independent projected-gradient solve in
// tests/test_hardness.cpp.
//
// --check (a few seconds): on a 64^2 sphere, every row's pressure flat at H on the plastic cells,
// A H / W -> 1 (within 2 %) at H = p0 / 10, the unloading depth unchanged; on a 128^2 rough
// surface, the plastic share ordered soft coating > steel > TiN at the same load.
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "contact/plastic_report.hpp"
#include "convolution/operators/make_operator.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using tables::format_number;

const Material kSteel(210e9, 0.3);
constexpr double kSlope = 0.05;   // rms slope of the rough surface
constexpr double kLength = 1e-3;  // its period [m]

struct Body {
  std::string label;
  LayerStack stack;
  double hardness;  // [Pa]
};

// Hardness values (Vickers, in Pa) of the surfaces: a hardened steel (about 60 HRC), TiN films
// (20 GPa) and a wrought aluminium alloy (about 1 GPa); the cap is the hardness of the contacting
// surface (docs/contact.md, "Hardness": how to choose it for a coating).
std::vector<Body> bodies() {
  return {{"steel (H = 7 GPa)", LayerStack(kSteel), 7e9},
          {"TiN 2 um on steel (H = 20 GPa)",
           LayerStack({{Material(400e9, 0.25), 2e-6, Interface::bonded}}, kSteel), 20e9},
          {"aluminium alloy 2 um on steel (H = 1 GPa)",
           LayerStack({{Material(70e9, 0.33), 2e-6, Interface::bonded}}, kSteel), 1e9}};
}

Field rough_gap(const Grid& g) {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_slope = kSlope;
  spec.short_cutoff = 16 * g.dx();
  spec.long_cutoff = kLength / 4;
  spec.seed = 2004;
  const Field z = self_affine_surface(g, spec);
  return z.maxCoeff() - z;
}

ContactOptions capped(double hardness) {
  ContactOptions o;
  o.hardness = hardness;
  o.threads = 2;
  return o;
}

// One row of the sphere table: a rigid 10 mm ball at 5 N on steel, capped at `ratio` p0.
struct SphereRow {
  double ratio, plastic_radius, area_over_w_h, pressure_spread, unload_change, dent, approach;
  bool converged;
};

SphereRow sphere_row(std::ptrdiff_t n, double ratio) {
  const double radius = 0.01, load = 5.0;
  const HertzSphere hz = hertz_sphere_for_load(load, radius, kSteel.plane_strain_modulus());
  // The fully plastic contact's radius is sqrt(W / (pi H)): the domain holds 1.5 times it.
  const double reach =
      std::max(hz.contact_radius, std::sqrt(load / (std::numbers::pi * ratio * hz.max_pressure)));
  const Grid g(n, n, 3 * reach, 3 * reach);
  const BuiltOperator built = make_operator(g, LayerStack(kSteel), {});
  const double hardness = ratio * hz.max_pressure;
  ContactOptions options = capped(hardness);
  options.compute_approach = true;
  ContactSolver solver(*built.op, options);
  const Field h = height(g, Sphere{radius});
  const std::vector<ContactResult> cycle =
      solver.solve_sweep(h, ContactControl::load, {load / 4, load}, true);
  const ContactResult& peak = cycle[1];
  const Field plastic_cells = (peak.pressure >= hardness).cast<double>();
  SphereRow row{};
  row.ratio = ratio;
  row.plastic_radius =
      std::sqrt(plastic_cells.sum() * g.dx() * g.dy() / std::numbers::pi) / hz.contact_radius;
  row.area_over_w_h = peak.contact_area * hardness / load;
  // On the plastic cells the pressure is H exactly; spread = (max - min) / H there.
  row.pressure_spread = plastic_cells.sum() > 0
                            ? ((plastic_cells > 0).select(peak.pressure, -1e300).maxCoeff() -
                               (plastic_cells > 0).select(peak.pressure, 1e300).minCoeff()) /
                                  hardness
                            : 0.0;
  row.unload_change = (cycle[2].plastic_depth - peak.plastic_depth).abs().maxCoeff() /
                      std::max(peak.plastic_depth.maxCoeff(), 1e-300);
  row.dent = peak.plastic_depth.maxCoeff() / hz.approach;
  row.approach = *peak.approach / hz.approach;
  row.converged = cycle[0].converged && peak.converged && cycle[2].converged;
  return row;
}

std::string sphere_table(std::ptrdiff_t n) {
  std::ostringstream md;
  md << "\n## A sphere capped at H (rigid 10 mm ball, 5 N, steel, " << n << "^2 cells)\n\n"
     << "Loaded to W / 4 and W, unloaded to W / 4. p0, a and delta are Hertz's elastic values "
        "(p0 = "
     << format_number(
            "%.3g",
            hertz_sphere_for_load(5.0, 0.01, kSteel.plane_strain_modulus()).max_pressure / 1e9)
     << " GPa). c: the radius of the disk of the plastic cells' area; spread: (max - min) / H of "
        "the pressure on them (flat at H); dent: the largest plastic depth, the residual dent "
        "after unloading; unload change: how far the unloading moved the depth.\n\n"
     << "| H / p0 | c / a | A H / W | spread | dent / delta | delta_capped / delta | "
        "unload change | converged |\n|---|---|---|---|---|---|---|---|\n";
  for (const double ratio : {1.2, 0.9, 0.7, 0.5, 0.3, 0.1}) {
    const SphereRow r = sphere_row(n, ratio);
    md << "| " << ratio << " | " << format_number("%.3f", r.plastic_radius) << " | "
       << format_number("%.4f", r.area_over_w_h) << " | "
       << format_number("%.1e", r.pressure_spread) << " | " << format_number("%.4f", r.dent)
       << " | " << format_number("%.4f", r.approach) << " | "
       << format_number("%.1e", r.unload_change) << " | " << (r.converged ? "yes" : "no") << " |\n";
  }
  md << "\nAbove p0 nothing flows. As H falls the plastic disk grows towards the whole contact "
        "and A H / W falls towards 1: the load rests on cells at H. The unloading leaves the "
        "depth as it was (it is elastic).\n";
  return md.str();
}

// A rough surface's cycle on one body: rows per load of the loading branch, and the last
// unloading step's.
struct RoughRow {
  double load, area, plastic_share, max_depth, mean_depth;
  bool converged;
};

std::vector<RoughRow> rough_cycle(const Grid& g, const Field& gap, const Body& b,
                                  const std::vector<double>& loads) {
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  o.threads = 2;
  const BuiltOperator built = make_operator(g, b.stack, o);
  ContactSolver solver(*built.op, capped(b.hardness));
  const double scale = kSteel.plane_strain_modulus() * kSlope * g.lx() * g.ly();
  std::vector<double> newtons;
  for (const double l : loads) newtons.push_back(l * scale);
  const std::vector<ContactResult> cycle =
      solver.solve_sweep(gap, ContactControl::load, newtons, true);
  std::vector<RoughRow> rows;
  for (const ContactResult& r : cycle) {
    const PlasticReport p = plastic_report(r, b.hardness, g);
    rows.push_back({r.load / scale, r.contact_area / (g.lx() * g.ly()), p.plastic_area_fraction,
                    p.max_plastic_depth, p.plastic_volume / (g.lx() * g.ly()), r.converged});
  }
  return rows;
}

const std::vector<double> kLoads{0.005, 0.01, 0.02, 0.04};

std::string rough_table(std::ptrdiff_t n) {
  const Grid g(n, n, kLength, kLength);
  const Field gap = rough_gap(g);
  std::ostringstream md;
  md << "\n## Plastic area and residual depth of a rough surface (" << n << "^2 cells)\n\n"
     << "A self-affine surface (Hurst 0.8, rms slope " << kSlope
     << ", shortest wavelength 16 cells = " << format_number("%.3g", 16e6 * g.dx())
     << " um, roll-off at a quarter of the 1 mm period, seed 2004) pressed by a rigid flat, "
        "periodic, loaded through p_m / (E* g) = 0.005 to 0.04 (E* of steel) and unloaded. "
        "Plastic share: of the contact area; the depths are the permanent ones (the residual "
        "surface after unloading from that load), the mean over the nominal area.\n\n"
     << "| body | p_m / (E* g) | A / A0 | plastic share | max depth [nm] | mean depth [nm] |\n"
        "|---|---|---|---|---|---|\n";
  bool all = true;
  for (const Body& b : bodies()) {
    const std::vector<RoughRow> rows = rough_cycle(g, gap, b, kLoads);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const RoughRow& r = rows[k];
      all = all && r.converged;
      const bool unloaded = k + 1 == rows.size();
      md << "| " << (k == 0 ? b.label : "") << " | " << format_number("%.3g", r.load)
         << (unloaded ? " (unloaded)" : "") << " | " << format_number("%.4f", r.area) << " | "
         << format_number("%.3f", r.plastic_share) << " | "
         << format_number("%.3g", 1e9 * r.max_depth) << " | "
         << format_number("%.3g", 1e9 * r.mean_depth) << " |\n";
    }
  }
  md << "\n"
     << (all ? "Every solve converged to 1e-10." : "NOT every solve converged.")
     << " On steel a third of the contact flows at every load and the summits keep dents of "
        "half a micrometre and more. TiN carries the same loads on less area and no cell reaches "
        "its hardness: the coating stays elastic (whether the steel under it yields is a "
        "question for `[stress]`: the von Mises stress at the interface against the steel's "
        "yield stress; the model's subsurface does not yield). The soft coating flows almost "
        "everywhere it touches, on an area near W / H, and its dents reach past its own "
        "thickness: there the coating's hardness no longer describes the surface (the film "
        "rule wants depths within a tenth of the thickness; docs/contact.md, \"Hardness\"), "
        "so these rows show the model's answer, not the coated part's. Unloading leaves every "
        "depth as it was, and the contact wider than on loading (the dents conform).\n";
  return md.str();
}

int check() {
  tables::Checks checks("hardness_table");
  for (const double ratio : {0.7, 0.1}) {
    const SphereRow r = sphere_row(64, ratio);
    const std::string name = "sphere, H / p0 = " + format_number("%.1f", ratio);
    checks.expect(r.converged, name, "did not converge");
    checks.expect(r.pressure_spread == 0.0, name + ": flat at H",
                  format_number("%.1e", r.pressure_spread));
    checks.expect(r.unload_change < 1e-9, name + ": unloading keeps the depth",
                  format_number("%.1e", r.unload_change));
    if (ratio < 0.2)
      checks.expect(r.area_over_w_h >= 1.0 && r.area_over_w_h < 1.02, name + ": A H / W -> 1",
                    format_number("%.4f", r.area_over_w_h));
  }
  const Grid g(128, 128, kLength, kLength);
  const Field gap = rough_gap(g);
  std::vector<double> shares;
  for (const Body& b : bodies()) shares.push_back(rough_cycle(g, gap, b, {0.02})[0].plastic_share);
  checks.expect(shares[2] > shares[0] && shares[0] > shares[1],
                "rough, p_m / (E* g) = 0.02: plastic share soft > steel > TiN",
                format_number("%.3f", shares[2]) + ", " + format_number("%.3f", shares[0]) + ", " +
                    format_number("%.3f", shares[1]));
  return checks.finish();
}

int write_table(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream md;
  md << "# Validation: the hardness cap\n\n"
     << "Generated by `hardness_table` (tables/hardness_table.cpp; "
        "`scripts/make_validation_docs.sh` runs it). The contact pressure capped at the "
        "hardness H of the surface, the overlap of the cells at H its plastic depth "
        "(elastic-perfectly-plastic surface: Tian & Bhushan 1996, Almqvist et al. 2007; "
        "docs/contact.md, \"Hardness\"). Every solve to 1e-10. The box-constrained problem "
        "itself agrees with an independent projected-gradient solve to 6e-12 of H "
        "(tests/test_hardness.cpp).\n"
     << sphere_table(128) << rough_table(512);
  return tables::write_table_file(output, md.str(), start);
}

}  // namespace

int main(int argc, char** argv) {
  return tables::table_main(argc, argv,
                            {"hardness_table", "The hardness cap: limits, rough bodies",
                             "docs/validation/hardness.md", check, write_table});
}
