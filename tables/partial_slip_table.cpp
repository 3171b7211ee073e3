// Validation of partial slip (contact/partial_slip.hpp), written to
// docs/validation/partial_slip.md:
//  - a rigid sphere on a nearly incompressible half-space (nu = 0.4999, where the tractions leave
//    the pressure as it is) against Cattaneo-Mindlin (Johnson 1985, 7.2): the stick radius, the
//    tangential shift and the traction field at Q = 0.3, 0.6, 0.9 mu P, on grids of a/dx = 8 to
//    32; and the energy of a fretting cycle 0 -> Q* -> -Q* -> Q* against Mindlin & Deresiewicz's
//    (Johnson 1985 eq. 7.59);
//  - a rigid sphere on coated steel under the same cycle (Q* = 0.6 mu P): a coating of the
//    substrate's own material against the bare steel, a thick TiN coating against the TiN
//    half-space, a thin stiff (TiN) and a thin soft (aluminium) coating against them: the stick
//    radius, the shift at Q*, the loop's energy, and the coupling's effect (the normal solves it
//    took, the pressure's change against the contact without tractions).
//
// --check, at the tolerances of the measured values (in brackets): at a/dx = 8 the stick radius
// within 3 % of Cattaneo's (2 %), the shift within 1 % (0.2 %), the rms traction error below 2 %
// of mu p0 (1.6 %); the loop energy within 8 % of eq. 7.59 (6.2 % at Q* = 0.5 mu P); the steel
// coating's stick radius, shift and loop energy equal to bare steel's within 2e-3 (the layered
// kernels' accuracy); every step converged.
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "contact/indenter.hpp"
#include "contact/partial_slip.hpp"
#include "convolution/operators/make_operator.hpp"
#include "materials/catalog.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/cattaneo_mindlin.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using tables::format_number;

constexpr double kBall = 0.01, kMu = 0.3;

std::string fixed(double v, int digits = 4) {
  return format_number(digits == 4 ? "%.4f" : "%.3f", v);
}

OperatorOptions exact_options(const LayerStack& body) {
  OperatorOptions o;
  o.method = exact_method(body);
  return o;
}

// A rigid sphere pressed with `load` on `body`, free surface, the grid 4a + 1 cells wide at
// a/dx = `cells` (a the Hertz radius of `reference`, the half-space the row is compared with).
struct SphereContact {
  Grid grid;
  BuiltOperator normal;
  RelativeSurfaceResponse response;
  Field h;
  SphereContact(const LayerStack& body, double a, int cells)
      : grid(4 * cells + 1, 4 * cells + 1, (4 * cells + 1) * a / cells,
             (4 * cells + 1) * a / cells),
        normal(make_operator(grid, body, exact_options(body))),
        response(make_tangential_operator(grid, body).op),
        h(height(grid, Sphere{kBall})) {}

  // The cycle 0 -> Q*/2 -> Q* -> 0 -> -Q* -> 0 -> Q* under `load`.
  std::vector<PartialSlipResult> cycle(double load, double q_star) {
    ContactSolver solver(*normal.op);
    PartialSlipOptions o;
    o.friction = kMu;
    return solve_partial_slip_path(solver, response, h, ContactControl::load, load,
                                   TangentialControl::load,
                                   {0.5 * q_star, q_star, 0.0, -q_star, 0.0, q_star}, o);
  }
};

// Cattaneo-Mindlin's case: 20 N on E = 2 GPa, nu = 0.4999.
const Material kRubber(2e9, Material::max_poisson_ratio);
CattaneoMindlin cattaneo() {
  return cattaneo_mindlin(20.0, kBall, kRubber, kMu);
}

struct ReferenceRow {
  int cells;
  double share;
  double stick, shift, rms;
  bool converged;
};

ReferenceRow reference_row(int cells, double share) {
  const CattaneoMindlin cm = cattaneo();
  SphereContact c(LayerStack(kRubber), cm.hertz.contact_radius, cells);
  ContactSolver solver(*c.normal.op);
  PartialSlipOptions o;
  o.friction = kMu;
  const double q = share * kMu * 20.0;
  const PartialSlipResult r = solve_partial_slip(
      solver, c.response, c.h, ContactControl::load, 20.0, TangentialControl::load, q, o,
      rest_state(c.response, solver.solve_load(c.h, 20.0)));
  return {cells,
          share,
          std::sqrt(r.stick_area / std::numbers::pi) / cm.stick_radius(q),
          r.tangential_shift / cm.shift(q),
          rms_traction_error(c.grid, r.qx, cm, q),
          r.converged};
}

// The loop's energy over eq. 7.59's at Q* = 0.5 mu P.
double loop_ratio(int cells, bool& converged) {
  const CattaneoMindlin cm = cattaneo();
  SphereContact c(LayerStack(kRubber), cm.hertz.contact_radius, cells);
  const double q_star = 0.5 * kMu * 20.0;
  const std::vector<PartialSlipResult> r = c.cycle(20.0, q_star);
  converged = true;
  for (const PartialSlipResult& step : r) converged = converged && step.converged;
  return (r[5].dissipated_energy - r[1].dissipated_energy) / cm.loop_energy(q_star);
}

// A coated row: the sphere pressed with 10 N on the body, at a/dx = 16 of bare steel's radius.
struct BodyRow {
  std::string label;
  double stick_over_a, shift, energy, pressure_change;
  int coupling_solves;
  bool converged;
};

constexpr double kCoatedLoad = 10.0;

BodyRow body_row(const std::string& label, const LayerStack& body, int cells) {
  const Material steel = material_by_name("steel");
  const double a =
      hertz_sphere_for_load(kCoatedLoad, kBall, steel.plane_strain_modulus()).contact_radius;
  SphereContact c(body, a, cells);
  const double q_star = 0.6 * kMu * kCoatedLoad;
  const std::vector<PartialSlipResult> r = c.cycle(kCoatedLoad, q_star);
  ContactSolver solver(*c.normal.op);
  const ContactResult rest = solver.solve_load(c.h, kCoatedLoad);
  BodyRow row{label, 0, 0, 0, 0, 0, true};
  const PartialSlipResult& at_star = r[1];
  row.stick_over_a = std::sqrt(at_star.stick_area / std::numbers::pi) /
                     std::sqrt(rest.contact_area / std::numbers::pi);
  row.shift = at_star.tangential_shift;
  row.energy = r[5].dissipated_energy - r[1].dissipated_energy;
  row.pressure_change =
      (at_star.normal.pressure - rest.pressure).abs().maxCoeff() / rest.pressure.maxCoeff();
  row.coupling_solves = at_star.coupling_solves;
  for (const PartialSlipResult& step : r) row.converged = row.converged && step.converged;
  return row;
}

std::vector<std::pair<std::string, LayerStack>> coated_bodies(double a) {
  const Material steel = material_by_name("steel"), tin = material_by_name("titanium_nitride"),
                 aluminium = material_by_name("aluminium");
  return {{"steel (half-space)", LayerStack(steel)},
          {"steel coating, h = a, on steel", LayerStack({Coating{steel, a}}, steel)},
          {"TiN (half-space)", LayerStack(tin)},
          {"TiN, h = 5a, on steel", LayerStack({Coating{tin, 5 * a}}, steel)},
          {"TiN, h = 0.2a, on steel (thin stiff)", LayerStack({Coating{tin, 0.2 * a}}, steel)},
          {"aluminium, h = 0.2a, on steel (thin soft)",
           LayerStack({Coating{aluminium, 0.2 * a}}, steel)},
          {"aluminium (half-space)", LayerStack(aluminium)}};
}

double steel_radius() {
  return hertz_sphere_for_load(kCoatedLoad, kBall, material_by_name("steel").plane_strain_modulus())
      .contact_radius;
}

int check() {
  tables::Checks checks("partial_slip_table");
  const ReferenceRow r = reference_row(8, 0.6);
  checks.expect(r.converged, "Cattaneo a/dx = 8", "converged");
  checks.expect(std::abs(r.stick - 1) < 0.03, "Cattaneo a/dx = 8",
                "stick radius " + fixed(r.stick) + " of Cattaneo's, not within 3 %");
  checks.expect(std::abs(r.shift - 1) < 0.01, "Cattaneo a/dx = 8",
                "shift " + fixed(r.shift) + " of Cattaneo-Mindlin's, not within 1 %");
  checks.expect(r.rms < 0.02, "Cattaneo a/dx = 8", "rms traction error " + fixed(r.rms));
  bool loop_converged = false;
  const double loop = loop_ratio(8, loop_converged);
  checks.expect(loop_converged && std::abs(loop - 1) < 0.08, "loop a/dx = 8",
                "energy " + fixed(loop) + " of eq. 7.59, not within 8 %");
  const double a = steel_radius();
  const auto bodies = coated_bodies(a);
  const BodyRow bare = body_row(bodies[0].first, bodies[0].second, 8);
  const BodyRow same = body_row(bodies[1].first, bodies[1].second, 8);
  for (const BodyRow* row : {&bare, &same}) checks.expect(row->converged, row->label, "converged");
  for (const auto& [name, ours, theirs] :
       {std::tuple{"stick radius", same.stick_over_a, bare.stick_over_a},
        {"shift", same.shift, bare.shift},
        {"loop energy", same.energy, bare.energy}})
    checks.expect(std::abs(ours / theirs - 1) < 2e-3, "steel coating on steel",
                  std::string(name) + " " + format_number("%.6g", ours) + " against bare " +
                      format_number("%.6g", theirs));
  return checks.finish();
}

int write_table(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream md;
  md << "# Partial slip\n\n"
     << "Generated by `tables/partial_slip_table.cpp` (`partial_slip_table --check` runs a subset "
        "as a test). A rigid sphere (R = 10 mm, mu = 0.3) on a free surface, the grid 4a + 1 "
        "cells wide; tolerance 1e-8 of the tangential iteration (docs/contact.md, \"Partial "
        "slip\").\n\n"
     << "## Cattaneo-Mindlin\n\n"
     << "20 N on E = 2 GPa, nu = 0.4999 (the tractions leave the pressure as it is, the "
        "references' assumption), Q loaded from rest in one step. Stick radius from the stick "
        "area, sqrt(A_stick / pi), over Cattaneo's c = a (1 - Q/(mu P))^(1/3); the tangential "
        "shift over 3 mu P (2 - nu)/(16 G a) [1 - (1 - Q/(mu P))^(2/3)]; the rms error of q_x "
        "over the Hertz disk against Cattaneo's traction, over mu p0.\n\n"
     << "| a/dx | Q/(mu P) | stick radius / Cattaneo's | shift / Cattaneo-Mindlin's | rms "
        "traction error / (mu p0) | converged |\n| --- | --- | --- | --- | --- | --- |\n";
  for (const int cells : {8, 16, 32})
    for (const double share : {0.3, 0.6, 0.9}) {
      const ReferenceRow r = reference_row(cells, share);
      md << "| " << cells << " | " << share << " | " << fixed(r.stick) << " | " << fixed(r.shift)
         << " | " << fixed(r.rms) << " | " << (r.converged ? "yes" : "no") << " |\n";
    }
  md << "\n## Mindlin-Deresiewicz\n\n"
     << "The same contact under 0 -> Q*/2 -> Q* -> 0 -> -Q* -> 0 -> Q*, Q* = 0.5 mu P: the "
        "friction "
        "work from the first Q* to the last (one cycle) over Johnson's (1985) eq. 7.59, the area "
        "of Masing's loop.\n\n| a/dx | cycle's friction work / eq. 7.59 | converged |\n"
        "| --- | --- | --- |\n";
  for (const int cells : {8, 16, 32}) {
    bool converged = false;
    const double ratio = loop_ratio(cells, converged);
    md << "| " << cells << " | " << fixed(ratio) << " | " << (converged ? "yes" : "no") << " |\n";
  }
  const double a = steel_radius();
  md << "\n## Coated steel\n\n"
     << "10 N (a = " << format_number("%.1f", a * 1e6)
     << " um on bare steel), the cycle above with Q* = 0.6 mu P, a/dx = 16 of bare steel's a. "
        "Stick radius at Q* over the contact's equivalent radius; the shift at Q*; the cycle's "
        "friction work; the coupling's effect: the normal solves of the step to Q* and the "
        "largest change of the pressure against the contact without tractions, over its peak "
        "(zero where the two surfaces' couplings cancel: an incompressible body, or one whose "
        "surface material is the indenter's).\n\n"
     << "| body | stick radius / contact radius | shift at Q* [nm] | cycle's energy [nJ] | "
        "normal solves | pressure change | converged |\n| --- | --- | --- | --- | --- | --- | --- "
        "|\n";
  for (const auto& [label, body] : coated_bodies(a)) {
    const BodyRow r = body_row(label, body, 16);
    md << "| " << r.label << " | " << fixed(r.stick_over_a, 3) << " | "
       << format_number("%.2f", r.shift * 1e9) << " | " << format_number("%.4f", r.energy * 1e9)
       << " | " << r.coupling_solves << " | " << format_number("%.4f", r.pressure_change) << " | "
       << (r.converged ? "yes" : "no") << " |\n";
  }
  md << "\n";
  return tables::write_table_file(output, md.str(), start);
}

}  // namespace

int main(int argc, char** argv) {
  return tables::table_main(
      argc, argv,
      {"partial_slip_table", "Partial slip against Cattaneo-Mindlin, and on coated steel",
       "docs/validation/partial_slip.md", check, write_table});
}
