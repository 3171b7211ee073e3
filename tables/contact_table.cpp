// Contact solver against closed forms on DC-FFT (docs/validation/contact.md):
//  - Hertz sphere under load control: errors in the contact radius sqrt(A/pi), the peak pressure
//    and the approach, and, under approach control at the Hertz approach, the error in the load;
//  - rigid flat punch under approach control: error in the load against W = 2 a E* delta;
//  - coated sphere on the frf-split operator: coating = substrate against the bare substrate,
//    stiff and soft coatings, and the thick- and thin-coating limits (the coating's and the
//    substrate's Hertz solutions).
// Writes docs/validation/contact.md and prints the same Markdown.
//
// --check: the Hertz and punch rows at N = 64 and 128 and the coated rows that the trends rest
// on, held to the bounds of the contact tests: Hertz a within dx/2, p0 and delta within
// 0.5 (dx/a)^2, W(delta) within 1.5 x 0.5 (dx/a)^2, min gap >= -1e-12 delta at tolerance 1e-12;
// punch W within 0.25 dx/a; every solve converged inside the domain; coating = substrate equal to
// bare steel (pressure to 1e-8 of p0, same contact area); the stiff coating shrinks the contact
// (a < 0.95 a_bare) and raises the peak (> 1.1 p_bare), the soft one the reverse (a > 1.1 a_bare,
// p < 0.8 p_bare); the stiff coating's peak tends to the coating half-space's as h grows
// (h = 100 a0 within 1e-6 and 100x closer than h = 10 a0) and to bare steel's as h falls
// (h = 1e-3 a0 within 5e-3 and 5x closer than h = 1e-2 a0); both half-spaces' peaks within 1 %
// of Hertz.
#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/grid.hpp"
#include "core/types.hpp"
#include "layers/layer_stack.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using coatfft::tables::format_number;

constexpr double kModulus = 1e11;  // E* [Pa]
constexpr double kRadius = 0.01;   // sphere radius R [m]
constexpr double kLoad = 10.0;     // W [N]: a = 90.9 um, a/R = 0.009
// Half-width of the square domain in contact radii. DC-FFT is an exact linear convolution (no
// periodic images), so the domain only has to contain the contact; 1.5 a leaves half a radius of
// free surface around it and is the domain of hertz_dcfft_table, whose displacement errors
// therefore apply here.
constexpr double kHalfWidth = 1.5;

struct HertzRow {
  std::ptrdiff_t n;
  double cells_per_radius;  // a / dx
  double radius_error;      // sqrt(A/pi) / a - 1
  double pressure_error;    // max p / p0 - 1
  double approach_error;    // delta / (a^2/R) - 1
  int iterations;
  double residual;
  bool converged;
  double load_error;  // approach control at the Hertz approach: W / W_Hertz - 1
  int iterations_approach;
  bool converged_approach;
  double min_gap;        // min over all cells of gap / delta, load control, default tolerance
  double min_gap_tight;  // the same at tolerance 1e-12 (the gap on the contact ~ tolerance)
};

// min over all cells of gap / approach of a load-controlled solve.
double min_relative_gap(const ContactResult& res) {
  return res.gap.minCoeff() / res.approach.value_or(1.0);
}

HertzRow hertz_row(std::ptrdiff_t n) {
  const HertzSphere ref = hertz_sphere_for_load(kLoad, kRadius, kModulus);
  const double width = 2 * kHalfWidth * ref.contact_radius;
  const Grid grid(n, n, width, width);
  const BuiltOperator built = make_operator(love_kernel(grid, kModulus));
  SurfaceOperator& op = *built.op;
  const Field h = height(grid, Sphere{kRadius});
  ContactOptions opts;
  opts.compute_approach = true;
  ContactSolver solver(op, opts);
  const ContactResult res = solver.solve_load(h, kLoad);
  const ContactResult by_approach = solver.solve_approach(h, ref.approach);
  ContactOptions tight = opts;
  tight.tolerance = 1e-12;
  const ContactResult res_tight = ContactSolver(op, tight).solve_load(h, kLoad);
  return {n,
          ref.contact_radius / grid.dx(),
          res.contact_radius.value_or(0.0) / ref.contact_radius - 1,
          res.max_pressure / ref.max_pressure - 1,
          res.approach.value_or(0.0) / ref.approach - 1,
          res.iterations,
          res.residual,
          res.converged && !res.touches_boundary,
          by_approach.load / ref.load - 1,
          by_approach.iterations,
          by_approach.converged && !by_approach.touches_boundary,
          min_relative_gap(res),
          min_relative_gap(res_tight)};
}

struct PunchRow {
  std::ptrdiff_t n;
  double cells_per_radius;
  double load_error;    // W / (2 a E* delta) - 1
  double radius_error;  // sqrt(A/pi) / a - 1
  int iterations;
  double residual;
  bool converged;
};

PunchRow punch_row(std::ptrdiff_t n) {
  const double a = 1e-3;
  const double delta = 1e-6;
  const double width = 2 * kHalfWidth * a;
  const Grid grid(n, n, width, width);
  const BuiltOperator built = make_operator(love_kernel(grid, kModulus));
  SurfaceOperator& op = *built.op;
  // Edge radius 0.01 dx^2/delta: the edge rises to h = delta within 0.14 dx of r = a, so the
  // rounding is below the grid's resolution (a sharp punch for this grid).
  const Field h = height(grid, FlatPunch{a, 0.01 * grid.dx() * grid.dx() / delta});
  const ContactResult res = ContactSolver(op).solve_approach(h, delta);
  return {n,
          a / grid.dx(),
          res.load / flat_punch_load(a, delta, kModulus) - 1,
          res.contact_radius.value_or(0.0) / a - 1,
          res.iterations,
          res.residual,
          res.converged && !res.touches_boundary};
}

// Coated sphere: rigid paraboloid on steel with one bonded coating of the same Poisson ratio, so
// that the E ratio is also the E* ratio and the Hertz limits are simple powers of it.
const Material kSteel(210e9, 0.3);
constexpr double kCoatedLoad = 50.0;  // W [N]: a0 = 118 um on bare steel, R = kRadius
constexpr std::ptrdiff_t kCoatedN = 128;
// Domain [-3 a0, 3 a0]^2 (a0/dx = 21): a soft (E ratio 0.1) thick coating grows the contact to
// 10^(1/3) a0 = 2.15 a0.
constexpr double kCoatedHalfWidth = 3.0;

HertzSphere bare_hertz() {
  return hertz_sphere_for_load(kCoatedLoad, kRadius, kSteel.plane_strain_modulus());
}

struct CoatedSolve {
  double radius;    // sqrt(A/pi) / a0
  double pressure;  // max p / p0 (bare substrate's Hertz values)
  double approach;  // delta / delta0
  int iterations;
  bool converged;
  Field p;
  double area;  // contact area [m^2]
};

Grid coated_grid() {
  const double width = 2 * kCoatedHalfWidth * bare_hertz().contact_radius;
  return Grid(kCoatedN, kCoatedN, width, width);
}

// Load-controlled solve, relative to the bare substrate's Hertz values.
CoatedSolve solve_coated(SurfaceOperator& op) {
  const HertzSphere ref = bare_hertz();
  ContactOptions opts;
  opts.compute_approach = true;
  const ContactResult res =
      ContactSolver(op, opts).solve_load(height(op.grid(), Paraboloid{kRadius}), kCoatedLoad);
  return {res.contact_radius.value_or(0.0) / ref.contact_radius,
          res.max_pressure / ref.max_pressure,
          res.approach.value_or(0.0) / ref.approach,
          res.iterations,
          res.converged && !res.touches_boundary,
          res.pressure,
          res.contact_area};
}

// On the frf-split operator: the split kernel needs no g(0), so the approach is as accurate as
// the kernel.
CoatedSolve on_split_kernel(const LayerStack& body) {
  OperatorOptions options;
  options.method = Method::frf_split;
  return solve_coated(*make_operator(coated_grid(), body, options).op);
}

// A homogeneous body on Love's DC-FFT: a reference independent of the FRF route.
CoatedSolve on_love(const Material& material) {
  OperatorOptions options;
  options.method = Method::dcfft;
  return solve_coated(*make_operator(coated_grid(), LayerStack(material), options).op);
}

LayerStack coated_steel(double modulus_ratio, double thickness_over_a0) {
  return LayerStack({Coating{Material(modulus_ratio * kSteel.youngs_modulus(), 0.3),
                             thickness_over_a0 * bare_hertz().contact_radius, Interface::bonded}},
                    kSteel);
}

std::string fixed(double x, int digits = 4) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << x;
  return os.str();
}

std::string pct(double x) {
  std::ostringstream os;
  os.setf(std::ios::showpos);
  os.precision(3);
  os << 100 * x << " %";
  return os.str();
}

std::string sci(double x) {
  std::ostringstream os;
  os.precision(2);
  os << std::scientific << x;
  return os.str();
}

std::string converged_mark(const CoatedSolve& s) {
  return s.converged ? "" : " (NOT CONVERGED)";
}

void coated_section(std::ostringstream& md) {
  const HertzSphere ref = bare_hertz();
  md << "\n## Coated sphere (frf-split)\n\n"
     << "Rigid paraboloid R = " << kRadius << " m, load W = " << kCoatedLoad
     << " N, on steel (E = 210 GPa, nu = 0.3) with one\n"
     << "bonded coating of nu = 0.3 (so E1/E2 is also the E* ratio). a0, p0, delta0: Hertz on\n"
     << "bare steel, a0 = " << ref.contact_radius << " m, p0 = " << ref.max_pressure
     << " Pa, delta0 = " << ref.approach << " m.\n"
     << "Coated bodies on frf-split (split FRF kernel + DC-FFT), half-spaces on Love's DC-FFT;\n"
     << "N = " << kCoatedN << " on [-" << kCoatedHalfWidth << " a0, " << kCoatedHalfWidth
     << " a0]^2 (a0/dx = " << std::lround(kCoatedN / (2 * kCoatedHalfWidth))
     << "), load control, default solver options; a = sqrt(A/pi).\n\n";

  // Coating = substrate, stiff, soft, at h = a0.
  const CoatedSolve bare = on_love(kSteel);
  md << "Coating thickness h = a0:\n\n"
     << "| body | a / a0 | max p / p0 | delta / delta0 | max abs(p - p_bare) / p0 | "
        "iterations |\n"
     << "|---|---|---|---|---|---|\n";
  const auto row = [&](const std::string& name, const CoatedSolve& s) {
    md << "| " << name << " | " << fixed(s.radius) << " | " << fixed(s.pressure) << " | "
       << fixed(s.approach) << " | " << sci((s.p - bare.p).abs().maxCoeff() / ref.max_pressure)
       << " | " << s.iterations << converged_mark(s) << " |\n";
  };
  row("bare steel (Love DC-FFT)", bare);
  row("coating = substrate (E1/E2 = 1)", on_split_kernel(coated_steel(1.0, 1.0)));
  row("stiff coating, E1/E2 = 10", on_split_kernel(coated_steel(10.0, 1.0)));
  row("soft coating, E1/E2 = 0.1", on_split_kernel(coated_steel(0.1, 1.0)));

  // Thickness sweep: h/a0 -> infinity gives the coating's half-space, h/a0 -> 0 the substrate's.
  md << "\nThickness sweep: as h/a0 grows the contact tends to Hertz on the coating's half-space,"
     << "\nas h/a0 falls to Hertz on the substrate's (Hertz: a ~ E*^(-1/3), p0 ~ E*^(2/3)).\n\n"
     << "| h / a0 | stiff (E1/E2 = 10): a / a0 | max p / p0 | soft (E1/E2 = 0.1): a / a0 | "
        "max p / p0 |\n"
     << "|---|---|---|---|---|\n";
  const auto pair_row = [&](const std::string& label, const CoatedSolve& stiff,
                            const CoatedSolve& soft) {
    md << "| " << label << " | " << fixed(stiff.radius) << converged_mark(stiff) << " | "
       << fixed(stiff.pressure) << " | " << fixed(soft.radius) << converged_mark(soft) << " | "
       << fixed(soft.pressure) << " |\n";
  };
  pair_row("coating half-space, numerical", on_love(Material(2100e9, 0.3)),
           on_love(Material(21e9, 0.3)));
  md << "| coating half-space, Hertz | " << fixed(std::cbrt(0.1)) << " | "
     << fixed(std::cbrt(100.0)) << " | " << fixed(std::cbrt(10.0)) << " | "
     << fixed(std::cbrt(0.01)) << " |\n";
  for (const double h : {100.0, 10.0, 3.0, 1.0, 0.3, 0.1, 0.01, 0.001}) {
    std::ostringstream label;
    label << h;
    pair_row(label.str(), on_split_kernel(coated_steel(10.0, h)),
             on_split_kernel(coated_steel(0.1, h)));
    std::cerr << "coated h/a0 = " << h << " done\n";
  }
  pair_row("substrate half-space, numerical", bare, bare);
  md << "| substrate half-space, Hertz | 1 | 1 | 1 | 1 |\n";
}

// --check, the homogeneous rows: Hertz's sphere under load and approach control and the flat
// punch, at N = 64 and 128, each error within its discretisation bound.
void check_homogeneous(tables::Checks& checks) {
  const auto pct_of = [](double x) { return format_number("%+.3g", 100 * x) + " %"; };
  for (const std::ptrdiff_t n : {64, 128}) {
    const HertzRow r = hertz_row(n);
    const std::string row = "Hertz sphere | N = " + std::to_string(n);
    const double dx_over_a = 1.0 / r.cells_per_radius;
    const double tol2 = 0.5 * dx_over_a * dx_over_a;
    checks.expect(r.converged, row, "load control not converged inside the domain");
    checks.expect(r.converged_approach, row, "approach control not converged inside the domain");
    checks.expect(
        std::abs(r.radius_error) <= 0.5 * dx_over_a, row,
        "a error " + pct_of(r.radius_error) + " beyond dx/2 = " + pct_of(0.5 * dx_over_a));
    checks.expect(
        std::abs(r.pressure_error) <= tol2, row,
        "p0 error " + pct_of(r.pressure_error) + " beyond 0.5 (dx/a)^2 = " + pct_of(tol2));
    checks.expect(
        std::abs(r.approach_error) <= tol2, row,
        "delta error " + pct_of(r.approach_error) + " beyond 0.5 (dx/a)^2 = " + pct_of(tol2));
    checks.expect(std::abs(r.load_error) <= 1.5 * tol2, row,
                  "W(delta) error " + pct_of(r.load_error) +
                      " beyond 1.5 x 0.5 (dx/a)^2 = " + pct_of(1.5 * tol2));
    checks.expect(r.min_gap_tight >= -1e-12, row,
                  "min gap / delta at tolerance 1e-12 = " + sci(r.min_gap_tight) + " < -1e-12");
    const PunchRow punch = punch_row(n);
    const std::string punch_row_name = "flat punch | N = " + std::to_string(n);
    checks.expect(punch.converged, punch_row_name, "not converged inside the domain");
    checks.expect(std::abs(punch.load_error) <= 0.25 / punch.cells_per_radius, punch_row_name,
                  "W error " + pct_of(punch.load_error) +
                      " beyond 0.25 dx/a = " + pct_of(0.25 / punch.cells_per_radius));
  }
}

// --check, the coated sphere: each solve converged, and each coating against its limits (the
// substrate's own material, the coating's half-space when thick, the bare substrate when thin).
void check_coated(tables::Checks& checks) {
  const HertzSphere ref = bare_hertz();
  const CoatedSolve bare = on_love(kSteel);
  const CoatedSolve same = on_split_kernel(coated_steel(1.0, 1.0));
  const CoatedSolve stiff = on_split_kernel(coated_steel(10.0, 1.0));
  const CoatedSolve soft = on_split_kernel(coated_steel(0.1, 1.0));
  const CoatedSolve stiff_half_space = on_love(Material(2100e9, 0.3));
  const CoatedSolve thick = on_split_kernel(coated_steel(10.0, 10.0));
  const CoatedSolve thicker = on_split_kernel(coated_steel(10.0, 100.0));
  const CoatedSolve thin = on_split_kernel(coated_steel(10.0, 0.01));
  const CoatedSolve thinner = on_split_kernel(coated_steel(10.0, 0.001));
  const std::vector<std::pair<const char*, const CoatedSolve*>> solves = {
      {"bare steel", &bare},
      {"coating = substrate", &same},
      {"stiff, h = a0", &stiff},
      {"soft, h = a0", &soft},
      {"stiff half-space", &stiff_half_space},
      {"stiff, h = 10 a0", &thick},
      {"stiff, h = 100 a0", &thicker},
      {"stiff, h = 0.01 a0", &thin},
      {"stiff, h = 0.001 a0", &thinner}};
  for (const auto& [name, solve] : solves)
    checks.expect(solve->converged, std::string("coated sphere | ") + name,
                  "not converged inside the domain");
  const double same_difference = (same.p - bare.p).abs().maxCoeff() / ref.max_pressure;
  checks.expect(same_difference < 1e-8, "coated sphere | coating = substrate",
                "max |p - p_bare| / p0 = " + sci(same_difference) + " >= 1e-8");
  checks.expect(same.area == bare.area, "coated sphere | coating = substrate",
                "contact area differs from bare steel's");
  checks.expect(stiff.radius < 0.95 * bare.radius, "coated sphere | stiff, h = a0",
                "a / a0 = " + fixed(stiff.radius) + " not below 0.95 x bare " + fixed(bare.radius));
  checks.expect(
      stiff.pressure > 1.1 * bare.pressure, "coated sphere | stiff, h = a0",
      "max p / p0 = " + fixed(stiff.pressure) + " not above 1.1 x bare " + fixed(bare.pressure));
  checks.expect(soft.radius > 1.1 * bare.radius, "coated sphere | soft, h = a0",
                "a / a0 = " + fixed(soft.radius) + " not above 1.1 x bare " + fixed(bare.radius));
  checks.expect(
      soft.pressure < 0.8 * bare.pressure, "coated sphere | soft, h = a0",
      "max p / p0 = " + fixed(soft.pressure) + " not below 0.8 x bare " + fixed(bare.pressure));
  const auto relative = [](double x, double y) { return std::abs(x - y) / std::abs(y); };
  const double d_thick = relative(thick.pressure, stiff_half_space.pressure);
  const double d_thicker = relative(thicker.pressure, stiff_half_space.pressure);
  checks.expect(d_thicker < 0.01 * d_thick && d_thicker < 1e-6, "coated sphere | stiff, h = 100 a0",
                "peak pressure " + sci(d_thicker) + " from the coating half-space's (h = 10 a0: " +
                    sci(d_thick) + "), not below 1e-6 and 0.01 x that");
  const double t_thin = relative(thin.pressure, bare.pressure);
  const double t_thinner = relative(thinner.pressure, bare.pressure);
  checks.expect(t_thinner < 0.2 * t_thin && t_thinner < 5e-3, "coated sphere | stiff, h = 0.001 a0",
                "peak pressure " + sci(t_thinner) + " from bare steel's (h = 0.01 a0: " +
                    sci(t_thin) + "), not below 5e-3 and 0.2 x that");
  const double coating_hertz = std::cbrt(100.0);  // p0 ~ E*^(2/3), E1/E2 = 10
  checks.expect(relative(stiff_half_space.pressure, coating_hertz) < 0.01,
                "coated sphere | coating half-space, numerical",
                "max p / p0 = " + fixed(stiff_half_space.pressure) + " not within 1 % of Hertz " +
                    fixed(coating_hertz));
  checks.expect(relative(bare.pressure, 1.0) < 0.01,
                "coated sphere | substrate half-space, numerical",
                "max p / p0 = " + fixed(bare.pressure) + " not within 1 % of Hertz 1");
}

// --check: see the top of the file.
int check() {
  tables::Checks checks("contact_table");
  check_homogeneous(checks);
  check_coated(checks);
  return checks.finish();
}

int write_table(const std::string& path) {
  const std::vector<std::ptrdiff_t> sizes{64, 128, 256, 512};
  std::ostringstream md;
  const HertzSphere ref = hertz_sphere_for_load(kLoad, kRadius, kModulus);
  md << "# Contact solver validation (generated by `contact_table`)\n\n"
     << "`contact_table --check` (ctest `table_contact_check`) recomputes the Hertz and punch\n"
     << "rows at N = 64 and 128 and the coated rows the trends rest on, and holds them to the\n"
     << "bounds stated at the top of tables/contact_table.cpp.\n\n"
     << "Polonsky-Keer solver (contact/contact_solver.hpp, default options: |k|-preconditioned)\n"
     << "on the DC-FFT operator with Love's coefficients (coated bodies: frf-split);\n"
     << "tolerance 1e-10 (relative pressure change), FFTW_ESTIMATE. Timings and the classic\n"
     << "(unpreconditioned) iteration counts: bench_contact and docs/contact.md.\n\n"
     << "## Hertz sphere\n\n"
     << "Rigid exact sphere R = " << kRadius << " m on a half-space E* = " << kModulus
     << " Pa, load W = " << kLoad << " N: a = " << ref.contact_radius
     << " m, p0 = " << ref.max_pressure << " Pa, delta = " << ref.approach
     << " m (a/R = " << ref.contact_radius / kRadius
     << ",\nso the sphere/paraboloid difference, ~(a/R)^2/8 of "
     << "delta, is below 1e-5). Domain [-" << kHalfWidth << " a, " << kHalfWidth
     << " a]^2.\nLoad control for a (equivalent radius sqrt(A/pi) from the contact area),\n"
     << "p0 (largest cell pressure) and delta (mean of h + u over the contact); then approach\n"
     << "control at the Hertz delta for the load W. min gap: the smallest gap / delta over all\n"
     << "cells (the contact's gap is 0 up to the solver's tolerance), at the default tolerance\n"
     << "1e-10 and at 1e-12.\n\n"
     << "| N | a/dx | a error | p0 error | delta error | iterations | residual | "
        "W(delta) error | iterations (approach) | min gap (1e-10) | min gap (1e-12) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto n : sizes) {
    const HertzRow r = hertz_row(n);
    md << "| " << n << " | " << std::lround(r.cells_per_radius) << " | " << pct(r.radius_error)
       << " | " << pct(r.pressure_error) << " | " << pct(r.approach_error) << " | " << r.iterations
       << (r.converged ? "" : " (NOT CONVERGED)") << " | " << sci(r.residual) << " | "
       << pct(r.load_error) << " | " << r.iterations_approach
       << (r.converged_approach ? "" : " (NOT CONVERGED)") << " | " << sci(r.min_gap) << " | "
       << sci(r.min_gap_tight) << " |\n";
    std::cerr << "hertz n = " << n << " done\n";
  }
  md << "\n## Rigid flat punch\n\n"
     << "Punch radius a = 1 mm, approach delta = 1 um, E* = " << kModulus << " Pa, domain [-"
     << kHalfWidth << " a, " << kHalfWidth
     << " a]^2,\nedge radius 0.01 dx^2/delta (below the grid's resolution). "
     << "Reference W = 2 a E* delta (Boussinesq).\n\n"
     << "| N | a/dx | W error | sqrt(A/pi) error | iterations | residual |\n"
     << "|---|---|---|---|---|---|\n";
  for (const auto n : sizes) {
    const PunchRow r = punch_row(n);
    md << "| " << n << " | " << std::lround(r.cells_per_radius) << " | " << pct(r.load_error)
       << " | " << pct(r.radius_error) << " | " << r.iterations
       << (r.converged ? "" : " (NOT CONVERGED)") << " | " << sci(r.residual) << " |\n";
    std::cerr << "punch n = " << n << " done\n";
  }
  coated_section(md);
  std::cout << md.str();
  tables::write_text_file(path, md.str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tables::table_main(
      argc, argv,
      {"contact_table", "Contact solver against Hertz and the flat punch; coated contact trends",
       "docs/validation/contact.md", check, write_table});
}
