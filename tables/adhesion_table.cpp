// Adhesion with a Dugdale cohesive zone (contact/adhesive_contact.hpp; docs/contact.md,
// "Adhesion"): a sphere on a half-space against Maugis-Dugdale from near DMT to near JKR, a soft
// film on a stiff substrate from thick to thin against its two limits, and the pull-off of rough
// periodic surfaces, bare and coated. Writes docs/validation/adhesion.md.
//
// The references: Maugis-Dugdale (validation/maugis_dugdale.hpp) for the half-space and, since a
// thick film is the film's half-space, for the thick film; the Dugdale law on a Winkler
// foundation of the film's constrained modulus over its thickness (validation/winkler_dugdale.hpp)
// for the thin film on a rigid substrate. Each curve is followed under approach control, down
// through pull-off until the contact jumps off.
//
// --check (a few seconds; the half-space against Maugis-Dugdale is tests/test_adhesion.cpp's): on
// 128^2 grids, the thick film against the film's half-space (pull-off and contact radius at zero
// load within 2 %), the thin film against the Winkler limit (pull-off 1 %, load along the path
// 5 %, radius 3 %); a rough path on a coating of the substrate's own material equal to the
// half-space's, and a rough polymer's contact at least doubled by adhesion.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "contact/adhesive_contact.hpp"
#include "contact/indenter.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "layers/layer_stack.hpp"
#include "materials/material.hpp"
#include "surfaces/self_affine_surface.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/maugis_dugdale.hpp"
#include "validation/winkler_dugdale.hpp"

namespace {

using namespace coatfft;
using tables::format_number;
constexpr double pi = std::numbers::pi;

// A rigid ball (R = 1 mm) on a soft solid (E* = 1 GPa, nu = 0.3: a stiff polymer) with
// w = 0.05 J/m^2; sigma0 from Maugis' lambda on the soft solid's half-space.
constexpr double kRadius = 1e-3, kWork = 0.05, kModulus = 1e9, kNu = 0.3;
const Material kSoft(kModulus*(1 - kNu * kNu), kNu);

double k_maugis() {
  return 4 * kModulus / 3;
}
double a_scale() {
  return std::cbrt(pi * kWork * kRadius * kRadius / k_maugis());
}
double d_scale() {
  return std::cbrt(pi * pi * kWork * kWork * kRadius / (k_maugis() * k_maugis()));
}
double force_scale() {
  return pi * kWork * kRadius;
}
AdhesionOptions law(double lambda) {
  const double sigma0 = 0.5 * lambda * std::cbrt(pi * kWork * k_maugis() * k_maugis() / kRadius);
  return {kWork, kWork / sigma0};
}

// Love's coefficients for the half-space, the split kernel for a coated body.
OperatorOptions operator_options(const LayerStack& body) {
  OperatorOptions o;
  if (!body.is_homogeneous()) o.method = Method::frf_split;
  return o;
}

// A body's operator on a grid and the contact solver over it, built once for all their solves.
struct BodySolver {
  BodySolver(const Grid& g, const LayerStack& body)
      : built(make_operator(g, body, operator_options(body))), solver(*built.op) {}
  const Grid& grid() const { return built.op->grid(); }
  BuiltOperator built;
  ContactSolver solver;
};

// The approaches of a path: `steps` equal steps from `top` down to zero, then steps of 0.1
// Maugis' approach scale d_s on down (until the contact jumps off, or -3 d_s).
std::vector<double> approaches(double top, int steps = 20) {
  std::vector<double> d;
  for (int k = steps; k >= 0; --k) d.push_back(top * k / steps);
  for (int k = 1; k <= 30; ++k) d.push_back(-0.1 * k * d_scale());
  return d;
}

// One approach path through pull-off.
struct Path {
  double pull_off = 0;     // the most tensile load [N]
  double worst_error = 0;  // the load against the reference along the path, relative (below)
  bool converged = true, touches = false;
};

// Follows `path` from the top; the load error at each step in contact is |P - P_ref| over the
// larger of |P_ref| and pi w R (relative where the load is large, to the adhesive force where it
// is small).
Path follow(BodySolver& s, const AdhesionOptions& a, const std::vector<double>& path,
            const std::function<double(double)>& reference) {
  ContactSolver& solver = s.solver;
  const Field h = height(s.grid(), Paraboloid{kRadius});
  Path p;
  AdhesiveResult last;
  bool first = true;
  for (const double delta : path) {
    last = solve_adhesive(solver, h, ContactControl::approach, delta, a, first ? nullptr : &last);
    first = false;
    p.converged = p.converged && last.converged;
    p.touches = p.touches || last.contact.touches_boundary;
    p.pull_off = std::min(p.pull_off, last.contact.load);
    const double r = reference(delta);
    if (last.contact_area > 0 && std::isfinite(r))
      p.worst_error = std::max(
          p.worst_error, std::abs(last.contact.load - r) / std::max(std::abs(r), force_scale()));
    if (last.jumped_off) break;
  }
  return p;
}

// The contact radius at zero load (load control from a cold start: the stable branch).
double zero_load_radius(BodySolver& s, const AdhesionOptions& a) {
  const AdhesiveResult r =
      solve_adhesive(s.solver, height(s.grid(), Paraboloid{kRadius}), ContactControl::load, 0.0, a);
  return r.converged ? std::sqrt(r.contact_area / pi) : std::nan("");
}

// Maugis-Dugdale's contact radius at zero load: bisection in log(m - 1) on the large-contact
// side of the pull-off (the load falls from +inf at m -> 1 to the pull-off).
double md_zero_load_radius(const MaugisDugdale& md) {
  double lo = std::log(1e-9), hi = lo;
  while (md.at(1 + std::exp(hi)).load > 0) hi += 0.05;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (md.at(1 + std::exp(mid)).load > 0 ? lo : hi) = mid;
  }
  return md.at(1 + std::exp(hi)).contact_radius;
}

Grid ball_grid(std::ptrdiff_t n, double span) {
  return Grid(n, n, span * a_scale(), span * a_scale());
}

// ---- The half-space against Maugis-Dugdale ------------------------------------------------

struct BallRow {
  double lambda, reference, coarse, fine, worst_error_fine;
  bool converged, touches;
};

BallRow ball_row(double lambda, std::ptrdiff_t n, double span) {
  const AdhesionOptions a = law(lambda);
  const MaugisDugdale md(kRadius, kModulus, kWork, a.range);
  const auto ref = [&](double d) { return md.load_at_approach(d); };
  const std::vector<double> path = approaches(2 * d_scale());
  BodySolver coarse(ball_grid(n / 2, span), LayerStack(kSoft));
  BodySolver fine(ball_grid(n, span), LayerStack(kSoft));
  const Path c = follow(coarse, a, path, ref), f = follow(fine, a, path, ref);
  return {lambda,
          md.pull_off_load() / force_scale(),
          c.pull_off / force_scale(),
          f.pull_off / force_scale(),
          f.worst_error,
          c.converged && f.converged,
          c.touches || f.touches};
}

std::string ball_table(std::ptrdiff_t n) {
  std::ostringstream md;
  md << "\n## A sphere on a half-space against Maugis-Dugdale\n\n"
     << "A rigid ball, R = 1 mm, on E* = 1 GPa with w = 0.05 J/m^2 (a_s = (pi w R^2 / K)^(1/3) = "
     << format_number("%.2f", 1e6 * a_scale())
     << " um, K = 4 E* / 3), sigma0 from lambda; a "
        "square of side L (larger at small lambda, whose cohesive zone reaches further), "
     << n / 2 << "^2 and " << n
     << "^2 cells. Pull-off: the most tensile load of the approach path (steps of 0.1 in Maugis' "
        "D), over pi w R; DMT's end is 2, JKR's 1.5. Load error: the largest difference from "
        "Maugis-Dugdale's load at the same approach along the path, while in contact, over the "
        "larger of that load and pi w R.\n\n"
     << "| lambda | L / a_s | a_s / dx (fine) | Maugis-Dugdale | coarse | fine | error coarse | "
        "error fine | load error (fine) | converged |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [lambda, span] : std::vector<std::pair<double, double>>{
           {0.1, 12.0}, {0.3, 6.0}, {0.5, 6.0}, {1.0, 6.0}, {2.0, 6.0}}) {
    const BallRow r = ball_row(lambda, n, span);
    md << "| " << lambda << " | " << span << " | " << format_number("%.0f", n / span) << " | "
       << format_number("%.4f", -r.reference) << " | " << format_number("%.4f", -r.coarse) << " | "
       << format_number("%.4f", -r.fine) << " | "
       << format_number("%.1f %%", 100 * std::abs(r.coarse / r.reference - 1)) << " | "
       << format_number("%.1f %%", 100 * std::abs(r.fine / r.reference - 1)) << " | "
       << format_number("%.3f", r.worst_error_fine) << " | " << (r.converged ? "yes" : "no")
       << (r.touches ? " (touches the border)" : "") << " |\n";
  }
  md << "\nFrom near DMT (lambda = 0.1: 1.95 pi w R) towards JKR (1.5) the coatfft pull-off "
        "follows "
        "Maugis-Dugdale. The error is first order in the cell, as the cohesive zone's edge is "
        "taken cell by cell: it halves from the coarse to the fine grid at lambda = 1 and 2. "
        "The zone narrows as lambda grows (about a_s / lambda), so the JKR end needs a_s / dx "
        "growing with lambda: at lambda = 2 and 43 cells per a_s the pull-off is 6 % above "
        "Maugis-Dugdale's; tests/test_adhesion_grid.cpp takes 102 cells for 2.5 %.\n";
  return md.str();
}

// ---- A soft film on a stiff substrate, thick to thin ---------------------------------------

// The film of the soft solid above on a substrate 10^4 times stiffer (a polymer on glass is
// 10^3 to 10^4): rigid to within the film's own compliance at the thicknesses below.
LayerStack film(double thickness) {
  return LayerStack({{kSoft, thickness, Interface::bonded}},
                    Material(1e4 * kSoft.youngs_modulus(), kNu));
}

struct FilmRow {
  double thickness, pull_off, radius_zero, thin_pull_off, thin_radius_zero, worst_thin;
  bool converged, touches;
};

// A film of `thickness` (infinite: the film's half-space, the thick limit) along its path, and the
// thin limit's values.
FilmRow film_row(double thickness, const Grid& g, const AdhesionOptions& a, int steps = 20) {
  const bool thick = std::isinf(thickness);
  std::optional<WinklerDugdale> thin;
  if (!thick) thin.emplace(kRadius, thin_film_stiffness(kSoft, thickness), kWork, a.range);
  const auto ref = [&](double d) { return thin ? thin->load_at_approach(d) : std::nan(""); };
  // From the smaller of 2 d_s and 3 times the thin limit's approach at zero load.
  const double top =
      thin ? std::min(2 * d_scale(), 3 * thin->approach_at_zero_load()) : 2 * d_scale();
  BodySolver s(g, thick ? LayerStack(kSoft) : film(thickness));
  const Path p = follow(s, a, approaches(top, steps), ref);
  FilmRow r{};
  r.thickness = thickness;
  r.pull_off = p.pull_off / force_scale();
  r.radius_zero = zero_load_radius(s, a);
  r.thin_pull_off = thin ? thin->pull_off_load() / force_scale() : std::nan("");
  r.thin_radius_zero = thin ? thin->contact_radius(thin->approach_at_zero_load()) : std::nan("");
  r.worst_thin = thin ? p.worst_error : std::nan("");
  r.converged = p.converged && std::isfinite(r.radius_zero);
  r.touches = p.touches;
  return r;
}

std::string film_table(std::ptrdiff_t n, double span, double lambda) {
  const AdhesionOptions a = law(lambda);
  const Grid g = ball_grid(n, span);
  const MaugisDugdale md(kRadius, kModulus, kWork, a.range);
  const double md_radius = md_zero_load_radius(md);
  std::ostringstream md_text;
  md_text << "\n## A soft film on a stiff substrate, thick to thin\n\n"
          << "The soft solid above (E* = 1 GPa, nu = 0.3) as a film of thickness t bonded to a "
             "substrate 10^4 times stiffer, the same ball and law (lambda = "
          << lambda << " on the film's half-space), " << n << "^2 cells over " << span
          << " a_s. Thick-film limit: the film's half-space (Maugis-Dugdale: pull-off "
          << format_number("%.4f", -md.pull_off_load() / force_scale())
          << " pi w R, contact radius at zero load a_0 = " << format_number("%.3f", 1e6 * md_radius)
          << " um). Thin-film limit: the Dugdale law on a Winkler foundation k = M / t (M the "
             "film's constrained modulus): pull-off 2 pi R (w + sigma0^2 / (2k)), tending to "
             "2 pi w R. Load error: the largest difference from the Winkler load along the path, "
             "over pi w R.\n\n"
          << "| t [um] | t / a_0 | pull-off / (pi w R) | Winkler's | a(P = 0) / a_0 | "
             "Winkler's | load error vs Winkler | converged |\n"
             "|---|---|---|---|---|---|---|---|\n";
  const double inf = std::numeric_limits<double>::infinity();
  for (const double t : {inf, 50e-6, 10e-6, 3e-6, 1e-6, 0.3e-6, 0.1e-6}) {
    const FilmRow r = film_row(t, g, a);
    md_text << "| " << (std::isinf(t) ? "inf (half-space)" : format_number("%g", 1e6 * t)) << " | "
            << (std::isinf(t) ? "inf" : format_number("%.3g", t / md_radius)) << " | "
            << format_number("%.4f", -r.pull_off) << " | "
            << (std::isinf(t) ? "-" : format_number("%.4f", -r.thin_pull_off)) << " | "
            << format_number("%.3f", r.radius_zero / md_radius) << " | "
            << (std::isinf(t) ? "-" : format_number("%.3f", r.thin_radius_zero / md_radius))
            << " | " << (std::isinf(t) ? "-" : format_number("%.3f", r.worst_thin)) << " | "
            << (r.converged ? "yes" : "no") << (r.touches ? " (touches the border)" : "") << " |\n";
  }
  md_text << "\nA thick film is the film's half-space (at t = 6 a_0 the pull-off within 0.1 % and "
             "the contact the same cells as the half-space's on this grid). As the film thins "
             "the substrate stiffens the contact: the contact radius at zero load falls to a "
             "third of the half-space's and the pull-off rises from Maugis-Dugdale's 1.6 to "
             "2 pi w R, the Winkler limit, which the film meets within 0.4 % in pull-off, 1 % in "
             "radius and 2 % in the load along the path at t = 0.1 um (t / a_0 = 0.012). "
             "Between the two (t near a_0 / 8) the pull-off passes through 2.04 pi w R, above both "
             "ends (Winkler's own value is higher still there: the film is not yet thin).\n";
  return md_text.str();
}

// ---- Rough periodic surfaces: the load and the area at pull-off ------------------------------

// A self-affine surface (Hurst 0.8, 100 um period, roll-off at a quarter of it, shortest
// wavelength 8 cells, rms height kRoughRms) against a rigid flat, periodic; the gap h = max z - z.
constexpr double kRoughLength = 100e-6;
constexpr double kRoughRms = 20e-9, kRoughRange = 5e-9;

Field rough_gap(const Grid& g) {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_height = kRoughRms;
  spec.short_cutoff = 8 * g.dx();
  spec.long_cutoff = kRoughLength / 4;
  spec.seed = 1992;
  const Field z = self_affine_surface(g, spec);
  return z.maxCoeff() - z;
}

struct RoughBody {
  std::string label;
  LayerStack stack;
};

std::vector<RoughBody> rough_bodies() {
  const Material glass(70e9, 0.22);
  return {{"polymer (E* = 1 GPa)", LayerStack(kSoft)},
          {"polymer 5 um on glass", LayerStack({{kSoft, 5e-6, Interface::bonded}}, glass)},
          {"polymer 1 um on glass", LayerStack({{kSoft, 1e-6, Interface::bonded}}, glass)},
          {"glass", LayerStack(glass)}};
}

struct RoughRow {
  double pull_off, contact_at_pull_off, cohesive_at_pull_off, dmt_pull_off;
  double top_area, top_area_without;
  bool converged;
};

// The approach path from `top` down through pull-off, and the same approaches without adhesion
// for the DMT estimate: the non-adhesive load minus sigma0 times the area within h0.
RoughRow rough_row(const Grid& g, const Field& h, const LayerStack& body, double top) {
  OperatorOptions o;
  o.boundary = Boundary::periodic;
  const BuiltOperator built = make_operator(g, body, o);
  ContactSolver solver(*built.op);
  const AdhesionOptions a{kWork, kRoughRange};
  const double cell = g.dx() * g.dy(), area = g.lx() * g.ly();
  RoughRow row{};
  row.converged = true;
  row.pull_off = 0;
  row.dmt_pull_off = 0;
  AdhesiveResult last;
  bool first = true;
  for (int k = 20; k >= -40; --k) {
    const double delta = top * k / 20;
    last = solve_adhesive(solver, h, ContactControl::approach, delta, a, first ? nullptr : &last);
    row.converged = row.converged && last.converged;
    if (first) row.top_area = last.contact_area / area;
    if (last.contact.load < row.pull_off) {
      row.pull_off = last.contact.load;
      row.contact_at_pull_off = last.contact_area / area;
      row.cohesive_at_pull_off = last.cohesive_area / area;
    }
    // DMT: the contact without adhesion, its gap's cells within h0 pulled at sigma0.
    const ContactResult plain =
        delta > 0 ? solver.solve(h, ContactControl::approach, delta) : ContactResult{};
    const Field gap = delta > 0 ? plain.gap : Field(h - delta);
    const double pulled = ((gap > 0) && (gap < a.range)).cast<double>().sum() * cell;
    const double dmt = (delta > 0 ? plain.load : 0.0) - a.strength() * pulled;
    row.dmt_pull_off = std::min(row.dmt_pull_off, dmt);
    if (first) row.top_area_without = plain.contact_area / area;
    first = false;
    if (last.jumped_off) break;
  }
  row.pull_off /= area;
  row.dmt_pull_off /= area;
  return row;
}

std::string rough_table(std::ptrdiff_t n) {
  const Grid g(n, n, kRoughLength, kRoughLength);
  const Field h = rough_gap(g);
  const double top = 2 * kRoughRms;
  std::ostringstream md;
  md << "\n## Rough periodic surfaces: the load and the area at pull-off\n\n"
     << "A self-affine surface (Hurst 0.8, rms height " << format_number("%g", 1e9 * kRoughRms)
     << " nm, period 100 um, roll-off at 25 um, shortest wavelength 8 cells, seed 1992) against a "
        "rigid flat, periodic, "
     << n << "^2 cells; w = 0.05 J/m^2, h0 = " << format_number("%g", 1e9 * kRoughRange)
     << " nm (sigma0 = " << format_number("%g", 1e-6 * kWork / kRoughRange)
     << " MPa). Approach path from 2 rms heights past the first touch down by 0.1 rms until the "
        "contact jumps off. Pull-off: the most tensile mean stress of the path; A_c, A_coh: the "
        "contact and cohesive areas there, over the nominal area. DMT estimate: the contact "
        "without adhesion at the same approaches, less sigma0 times the area of its gap within "
        "h0 (the adhesion of bodies too stiff for it to deform them; an estimate, not a limit "
        "the solver must reach: a touching cell resists its neighbours' pull). A(top): the "
        "contact area at the top of the path with and without adhesion (a half-space's is the "
        "same for every modulus without it).\n\n"
     << "| body | pull-off [kPa] | DMT estimate [kPa] | A_c | A_coh | A(top) | A(top), no "
        "adhesion | converged |\n|---|---|---|---|---|---|---|---|\n";
  for (const RoughBody& b : rough_bodies()) {
    const RoughRow r = rough_row(g, h, b.stack, top);
    md << "| " << b.label << " | " << format_number("%.4g", -1e-3 * r.pull_off) << " | "
       << format_number("%.4g", -1e-3 * r.dmt_pull_off) << " | "
       << format_number("%.4f", r.contact_at_pull_off) << " | "
       << format_number("%.4f", r.cohesive_at_pull_off) << " | "
       << format_number("%.4f", r.top_area) << " | " << format_number("%.4f", r.top_area_without)
       << " | " << (r.converged ? "yes" : "no") << " |\n";
  }
  md << "\nAdhesion pulls the soft surfaces into contact (the area at the top of the path 2 to 5 "
        "times the non-adhesive one) and holds them to a tensile load; glass barely deforms, "
        "its pull-off near the rigid estimate. A thin polymer film on glass is stiffer than the "
        "polymer at the asperities' scale and sticks less. These numbers belong to this "
        "discrete surface: the asperities are a few cells wide, and a finer grid of the same "
        "spectrum (shorter wavelengths) changes them, as roughness does.\n";
  return md.str();
}

int write_table(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream md;
  md << "# Adhesion: Dugdale cohesive zones against Maugis-Dugdale and the thin-film limit\n\n"
     << "Generated by `adhesion_table` (tables/adhesion_table.cpp); the solver is described in "
        "[contact.md](../contact.md), \"Adhesion\".\n";
  md << ball_table(256) << film_table(256, 8.0, 1.0) << rough_table(256);
  return tables::write_table_file(output, md.str(), start);
}

int check_table() {
  tables::Checks checks("adhesion_table");
  // The half-space against Maugis-Dugdale is tests/test_adhesion.cpp's; here the film's limits
  // and the rough surfaces, on 128^2 grids.
  const AdhesionOptions a = law(1.0);
  const Grid g = ball_grid(128, 8.0);
  const double inf = std::numeric_limits<double>::infinity();
  // Half the table's steps down to zero approach (the pull-offs lie at or below it).
  const FilmRow half = film_row(inf, g, a, 10), thick = film_row(50e-6, g, a, 10);
  const FilmRow thin = film_row(0.1e-6, g, a, 10);
  const bool films_converged = half.converged && thick.converged && thin.converged;
  checks.expect(films_converged, "films", "a path or a zero-load solve did not converge");
  // Measured: 0.4 % and 0 % (the same cells) from the half-space on the same grid.
  checks.expect(
      std::abs(thick.pull_off / half.pull_off - 1) < 0.02, "t = 50 um",
      detail::concat("pull-off ", -thick.pull_off, " against the half-space's ", -half.pull_off));
  checks.expect(std::abs(thick.radius_zero / half.radius_zero - 1) < 0.02, "t = 50 um",
                detail::concat("a(P = 0) ", thick.radius_zero, " against ", half.radius_zero));
  // Measured: 0.2 %, 2.8 % and 0.5 % from the Winkler limit.
  checks.expect(
      std::abs(thin.pull_off / thin.thin_pull_off - 1) < 0.01, "t = 0.1 um",
      detail::concat("pull-off ", -thin.pull_off, " against Winkler's ", -thin.thin_pull_off));
  checks.expect(thin.worst_thin < 0.05, "t = 0.1 um",
                detail::concat("load error ", thin.worst_thin, " against Winkler's"));
  checks.expect(
      std::abs(thin.radius_zero / thin.thin_radius_zero - 1) < 0.03, "t = 0.1 um",
      detail::concat("a(P = 0) ", thin.radius_zero, " against Winkler's ", thin.thin_radius_zero));
  // A rough path on the polymer and on 5 um of it on the polymer: the same body, so the same path
  // (the periodic coated kernel against the half-space's); adhesion at least doubles the area.
  const Grid rg(64, 64, kRoughLength, kRoughLength);
  const Field h = rough_gap(rg);
  const RoughRow bare = rough_row(rg, h, LayerStack(kSoft), 2 * kRoughRms);
  const RoughRow same =
      rough_row(rg, h, LayerStack({{kSoft, 5e-6, Interface::bonded}}, kSoft), 2 * kRoughRms);
  checks.expect(bare.converged && same.converged, "rough", "a path did not converge");
  checks.expect(
      std::abs(same.pull_off / bare.pull_off - 1) < 1e-6 &&
          same.contact_at_pull_off == bare.contact_at_pull_off,
      "rough, a coating of the substrate's material",
      detail::concat("pull-off ", same.pull_off, " Pa against the half-space's ", bare.pull_off));
  // Measured: 4.7 times at 256^2.
  checks.expect(bare.top_area > 2 * bare.top_area_without, "rough polymer",
                detail::concat("area ", bare.top_area, " against ", bare.top_area_without,
                               " without adhesion"));
  return checks.finish();
}

}  // namespace

int main(int argc, char** argv) {
  return coatfft::tables::table_main(
      argc, argv,
      {"adhesion_table",
       "Adhesion against Maugis-Dugdale, thick and thin films, rough pull-off "
       "(docs/validation/adhesion.md)",
       "docs/validation/adhesion.md", check_table, write_table});
}
