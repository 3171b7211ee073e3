// Validation of the stresses on planes inside homogeneous and coated bodies
// (stress/stress_operator.hpp) against independent references: Johnson's (1985) closed forms on
// the axis of a Hertz pressure and a uniform disk (eqs. 3.45, 3.28-3.29) and the maximum shear
// stress below a Hertz contact, Hamilton's (1983) full field of a sliding Hertz contact, and the
// Hankel integrals of the depth FRFs for coated bodies (validation/axisymmetric_stress.hpp). The
// load is the cell-averaged one (exact cell forces) on grids of cell a/m with the origin a cell
// centre (N = 4m + 1), so the error left is the piecewise-constant load plus the kernel's.
// Writes docs/validation/stress.md.
//
// --check: at a/16 (the errors are the load's discretisation, O(dx^2): four times those at a/32
// of the table), the homogeneous Hertz row y = 0 within 2e-3 p0 at z = a/4 and a (1.6e-3 and
// 4.9e-4 measured), the sliding Hertz plane z = a/2 within 1.2e-3 p0 of Hamilton everywhere
// (8.7e-4), the coatings E1/E2 = 0.1, h = a, bonded and frictionless within 1.2e-3 p0 of their
// Hankel references at z = h/2, h, 3a/2 (8.9e-4), and the frictionless interface's shear below
// 1e-12 p0.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/detail/timing.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "stress/stress_operator.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/axisymmetric_stress.hpp"
#include "validation/hertz_stress.hpp"
#include "validation/sinusoidal_stress.hpp"

namespace {

using namespace coatfft;
using tables::format_number;

constexpr double a = 1e-3;  // contact radius [m]
constexpr double p0 = 1.0;  // Pa: errors are then in units of p0

Grid grid_for(int m) {
  const int n = 4 * m + 1;
  return {n, n, n * a / m, n * a / m};
}

Field load_on(const Grid& g, AxisymmetricLoad load) {
  return load == AxisymmetricLoad::hertz ? hertz_pressure(g, p0, a, Sampling::cell_average)
                                         : uniform_disk_pressure(g, p0, a, Sampling::cell_average);
}

std::vector<PlaneStress> stresses(const Grid& g, const LayerStack& body, const Field& p,
                                  const Field* qx, const std::vector<double>& depths,
                                  int alpha = 16) {
  StressOperatorOptions o;
  o.kernel.alpha = alpha;
  o.kernel.threads = 2;
  o.tangential = qx != nullptr;
  std::vector<PlaneStress> s;
  make_stress_operator(g, body, depths, o)->apply(p, qx, nullptr, s);
  return s;
}

// Largest |error| [p0] of sigma_rr, sigma_tt, sigma_zz, tau_rz along the row y = 0, x >= 0 of
// each plane against the Hankel reference of the continuous load.
std::vector<double> row_errors(const Grid& g, const LayerStack& body, AxisymmetricLoad load,
                               const std::vector<double>& depths, int alpha = 16) {
  const std::vector<PlaneStress> s = stresses(g, body, load_on(g, load), nullptr, depths, alpha);
  const std::ptrdiff_t ic = g.centre_i(), j = g.centre_j();
  std::vector<double> r;
  for (std::ptrdiff_t i = ic; i < g.nx(); ++i) r.push_back(g.x(i));
  std::vector<double> errors;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    const auto ref = axisymmetric_stress_at(body, load, p0, a, r, depths[d]);
    double e = 0.0;
    for (std::size_t k = 0; k < r.size(); ++k) {
      const auto i = ic + static_cast<std::ptrdiff_t>(k);
      e = std::max(
          {e, std::abs(s[d][s_xx](i, j) - ref[k].srr), std::abs(s[d][s_yy](i, j) - ref[k].stt),
           std::abs(s[d][s_zz](i, j) - ref[k].szz), std::abs(s[d][s_xz](i, j) - ref[k].srz)});
    }
    errors.push_back(e / p0);
  }
  return errors;
}

// Largest |error| [p0] of all six components over each whole plane against Hamilton (1983).
std::vector<double> hamilton_errors(int m, double friction, const std::vector<double>& depths) {
  const Grid g = grid_for(m);
  const double nu = 0.3;
  const Field p = load_on(g, AxisymmetricLoad::hertz);
  const Field qx = friction * p;
  const auto s = stresses(g, LayerStack(Material(210e9, nu)), p, &qx, depths);
  std::vector<double> errors;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    double e = 0.0;
    for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
        const StressTensor h = hertz_sliding_stress(g.x(i), g.y(j), depths[d], p0, a, nu, friction);
        const double ref[6] = {h.xx, h.yy, h.zz, h.yz, h.xz, h.xy};
        for (int c = 0; c < 6; ++c) e = std::max(e, std::abs(s[d][c](i, j) - ref[c]));
      }
    errors.push_back(e / p0);
  }
  return errors;
}

struct CoatedCase {
  std::string label;
  LayerStack body;
  double h;  // total coating thickness [m]
};

std::vector<CoatedCase> coated_cases() {
  const Material substrate(1e11, 0.3);
  std::vector<CoatedCase> cases;
  for (Interface i : {Interface::bonded, Interface::frictionless})
    for (double ratio : {0.1, 10.0})
      for (double h : {0.1 * a, a}) {
        std::ostringstream label;
        label << "E1/E2 = " << ratio << ", h/a = " << h / a << ", "
              << (i == Interface::bonded ? "bonded" : "frictionless");
        cases.push_back(
            {label.str(), LayerStack({{Material(ratio * 1e11, 0.25), h, i}}, substrate), h});
      }
  cases.push_back({"two coatings: E 2, 0.5 x E2, h 0.1a + 0.2a, bonded",
                   LayerStack({{Material(2e11, 0.25), 0.1 * a, Interface::bonded},
                               {Material(0.5e11, 0.35), 0.2 * a, Interface::bonded}},
                              substrate),
                   0.3 * a});
  return cases;
}

std::string row(const std::vector<double>& values) {
  std::string text;
  for (double v : values) text += " | " + format_number("%.2e", v);
  return text + " |\n";
}

}  // namespace

namespace {

// Johnson (1985) eq. 3.45: (sigma_zz, sigma_rr) on the axis of a Hertz pressure [p0].
std::pair<double, double> hertz_axis(double z_over_a, double nu) {
  const double z = z_over_a;
  return {-1 / (1 + z * z), -((1 + nu) * (1 - z * std::atan(1 / z)) - 0.5 / (1 + z * z))};
}

// The vertex of the parabola through (x0 - h, y0), (x0, y1), (x0 + h, y2).
std::pair<double, double> vertex(double x0, double h, double y0, double y1, double y2) {
  const double d = (y0 - y2) / (2 * (y0 - 2 * y1 + y2));
  return {x0 + d * h, y1 - 0.25 * (y0 - y2) * d};
}

// The maximum of (sigma_tt - sigma_zz)/2 on the axis: from planes 0.02a apart (parabola through
// the three best) and from Johnson's closed form (the same, 1e-5 a apart).
std::string section_max_shear() {
  const double nu = 0.3;
  std::vector<double> z;
  for (int k = 0; k <= 8; ++k) z.push_back((0.40 + 0.02 * k) * a);
  std::ostringstream md;
  md << "\n## Maximum shear stress below a Hertz contact (nu = 0.3)\n\n"
     << "(sigma_tt - sigma_zz)/2 on the axis, from planes z/a = 0.40 ... 0.56 (step 0.02) and a "
        "parabola through the three largest; Johnson (1985) eq. 3.45 the same way with step "
        "1e-5 a. Published: 0.31 p0 at 0.48 a (Johnson 1985, section 3.4).\n\n"
     << "| source | tau_max / p0 | z / a |\n|---|---|---|\n";
  const auto closed = [&](double za) {
    const auto [szz, srr] = hertz_axis(za, nu);
    return 0.5 * (srr - szz);
  };
  double best = 0.40;
  for (double za = 0.40; za <= 0.56; za += 1e-5)
    if (closed(za) > closed(best)) best = za;
  const auto [zj, tj] = vertex(best, 1e-5, closed(best - 1e-5), closed(best), closed(best + 1e-5));
  md << "| Johnson eq. 3.45 | " << format_number("%.6f", tj) << " | " << format_number("%.6f", zj)
     << " |\n";
  for (int m : {16, 32}) {
    const Grid g = grid_for(m);
    const auto s = stresses(g, LayerStack(Material(210e9, nu)), load_on(g, AxisymmetricLoad::hertz),
                            nullptr, z);
    const auto c = g.centre_i();
    std::vector<double> tau;
    for (const PlaneStress& plane : s) tau.push_back(0.5 * (plane[s_yy](c, c) - plane[s_zz](c, c)));
    const auto k = std::max_element(tau.begin() + 1, tau.end() - 1) - tau.begin();
    const auto [zs, ts] = vertex(z[k] / a, 0.02, tau[k - 1], tau[k], tau[k + 1]);
    md << "| coatfft, dx = a/" << m << " | " << format_number("%.6f", ts) << " | "
       << format_number("%.6f", zs) << " |\n";
  }
  return md.str();
}

// The homogeneous Hertz pressure and uniform disk: the row y = 0 against the Hankel reference
// (equal to Johnson's and Boussinesq's closed forms to 1e-15: tests/test_axisymmetric_stress.cpp)
// as the grid is refined.
std::string section_homogeneous() {
  const std::vector<double> z{0.1 * a, 0.25 * a, 0.5 * a, a};
  std::ostringstream md;
  md << "\n## Homogeneous half-space: grid convergence\n\n"
     << "Largest |error| / p0 of sigma_rr, sigma_tt, sigma_zz, tau_rz along the row y = 0 "
        "(x >= 0, to the domain edge at 2a) against the Hankel reference, nu = 0.3, alpha = 16.\n\n"
     << "| load | dx | z = 0.1a | z = 0.25a | z = 0.5a | z = a |\n|---|---|---|---|---|---|\n";
  for (AxisymmetricLoad load : {AxisymmetricLoad::hertz, AxisymmetricLoad::uniform_disk})
    for (int m : {8, 16, 32, 64})
      md << "| " << (load == AxisymmetricLoad::hertz ? "Hertz" : "uniform disk") << " | a/" << m
         << row(row_errors(grid_for(m), LayerStack(Material(210e9, 0.3)), load, z));
  return md.str();
}

// The periodic images against alpha: Hertz at a/16, the plane z = a.
std::string section_alpha() {
  std::ostringstream md;
  md << "\n## The sampling lattice's period alpha\n\n"
     << "Hertz on the half-space at dx = a/16; largest |error| / p0 along y = 0 at z = a/4 and "
        "z = a. The images' share falls like alpha^-3 until the load's discretisation "
        "(about 2e-4 at z = a) is left.\n\n| alpha | z = a/4 | z = a | setup [s] "
        "|\n|---|---|---|---|\n";
  for (int alpha : {2, 4, 8, 16, 32}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto e = row_errors(grid_for(16), LayerStack(Material(210e9, 0.3)),
                              AxisymmetricLoad::hertz, {0.25 * a, a}, alpha);
    md << "| " << alpha << " | " << format_number("%.2e", e[0]) << " | "
       << format_number("%.2e", e[1]) << " | " << format_number("%.2f", detail::seconds_since(t0))
       << " |\n";
  }
  return md.str();
}

}  // namespace

namespace {

// The planes of a coated case: in the coating, on the interface (below), in the substrate.
std::vector<double> coated_depths(const CoatedCase& c) {
  return {0.5 * c.h, c.h, c.h + 0.5 * a};
}

std::string section_coated(int m) {
  std::ostringstream md;
  md << "\n## Coated bodies at dx = a/" << m << "\n\n"
     << "Hertz pressure; substrate E2 = 100 GPa, nu 0.3; coatings nu 0.25. Largest |error| / p0 "
        "of sigma_rr, sigma_tt, sigma_zz, tau_rz along y = 0 against the Hankel reference of the "
        "continuous load, on the planes z = h/2 (in the coating), z = h (the interface, from "
        "below) and z = h + a/2 (the substrate); alpha = 16.\n\n"
     << "| body | z = h/2 | z = h | z = h + a/2 |\n|---|---|---|---|\n";
  for (const CoatedCase& c : coated_cases())
    md << "| " << c.label
       << row(row_errors(grid_for(m), c.body, AxisymmetricLoad::hertz, coated_depths(c)));
  // The largest errors, in the thin coatings, are the load's discretisation: O(dx^2).
  const CoatedCase thin = coated_cases().front();
  md << "\nThe same for " << thin.label << " as the grid is refined: the error falls like dx^2, "
     << "the piecewise-constant load's rate, once the cells are smaller than the depth (z = h/2 = "
        "a/20 is 0.8, 1.6 and 3.2 cells deep), so the kernel adds nothing visible.\n\n"
     << "| dx | z = h/2 | z = h | z = h + a/2 |\n|---|---|---|---|\n";
  for (int k : {16, 32, 64})
    md << "| a/" << k
       << row(row_errors(grid_for(k), thin.body, AxisymmetricLoad::hertz, coated_depths(thin)));
  return md.str();
}

// The hard bodies of docs/validation/hard_cases.md, on planes a cell or more deep.
std::string section_hard() {
  const Material s(1e11, 0.3);
  struct Hard {
    std::string label;
    LayerStack body;
    std::vector<double> z;
  };
  const std::vector<Hard> bodies{
      {"thin stiff: h/a = 1e-3, E1/E2 = 100, bonded",
       LayerStack({{Material(1e13, 0.3), 1e-3 * a, Interface::bonded}}, s),
       {0.1 * a, 0.5 * a}},
      {"thick soft: h/a = 50, E1/E2 = 0.01, bonded",
       LayerStack({{Material(1e9, 0.3), 50 * a, Interface::bonded}}, s),
       {0.1 * a, 0.5 * a}},
      {"nu = 0.4999 coating, h/a = 0.1, E1/E2 = 0.1, bonded",
       LayerStack({{Material(1e10, 0.4999), 0.1 * a, Interface::bonded}}, s),
       {0.05 * a, 0.5 * a}},
      {"nu = 0.4999 coating, h/a = 0.1, E1/E2 = 0.1, frictionless",
       LayerStack({{Material(1e10, 0.4999), 0.1 * a, Interface::frictionless}}, s),
       {0.05 * a, 0.5 * a}}};
  std::ostringstream md;
  md << "\n## Hard bodies at dx = a/16\n\n"
     << "Hertz pressure; largest |error| / p0 along y = 0 against the Hankel reference (every "
        "value finite). A plane inside the 1e-3 a coating would be 1/60 of a cell deep: its "
        "kernel needs about 111 (L/z)^2 = 7e9 FRF evaluations and is refused.\n\n"
     << "| body | planes z/a | errors |\n|---|---|---|\n";
  for (const Hard& h : bodies) {
    const auto e = row_errors(grid_for(16), h.body, AxisymmetricLoad::hertz, h.z);
    md << "| " << h.label << " | " << h.z[0] / a << ", " << h.z[1] / a << " | "
       << format_number("%.2e", e[0]) << ", " << format_number("%.2e", e[1]) << " |\n";
  }
  return md.str();
}

std::string section_sliding() {
  const std::vector<double> z{0.1 * a, 0.25 * a, 0.5 * a};
  std::ostringstream md;
  md << "\n## Sliding Hertz contact against Hamilton (1983)\n\n"
     << "q_x = mu p on the half-space (nu = 0.3); largest |error| / p0 of all six components over "
        "the whole plane against Hamilton's closed forms (validation/hertz_stress.hpp).\n\n"
     << "| mu | dx | z = 0.1a | z = 0.25a | z = 0.5a |\n|---|---|---|---|---|\n";
  for (double mu : {0.0, 0.25})
    for (int m : {16, 32}) md << "| " << mu << " | a/" << m << row(hamilton_errors(m, mu, z));
  // The trailing edge's tension: the largest sigma_xx on shallow planes against Hamilton there.
  md << "\nThe tensile sigma_xx at the trailing edge (x = -a, y = 0), mu = 0.25, on the plane "
        "z = a/64 (Hamilton's surface value p0 [(1 - 2nu)/3 + (4 + nu) pi mu/8] = "
     << format_number("%.4f", (1 - 0.6) / 3 + 4.3 * 3.14159265358979 * 0.25 / 8) << " p0):\n\n"
     << "| dx | coatfft | Hamilton at z = a/64 |\n|---|---|---|\n";
  for (int m : {16, 32}) {
    const Grid g = grid_for(m);
    const Field p = load_on(g, AxisymmetricLoad::hertz);
    const Field qx = 0.25 * p;
    const auto s = stresses(g, LayerStack(Material(210e9, 0.3)), p, &qx, {a / 64});
    const std::ptrdiff_t i = g.centre_i() - m;  // x = -a
    md << "| a/" << m << " | " << format_number("%.4f", s[0][s_xx](i, g.centre_j())) << " | "
       << format_number("%.4f", hertz_sliding_stress(-a, 0, a / 64, p0, a, 0.3, 0.25).xx) << " |\n";
  }
  return md.str();
}

// The Hankel reference's own convergence: its fields at rel_tol 1e-6, 1e-8 and 1e-10 against
// those at 1e-12, at points in the coating, on the interface and in the substrate, inside and
// outside the load, for the thinnest soft and the thick stiff coating of the set.
double reference_change(const LayerStack& body, double h, double rel_tol) {
  const std::vector<double> r{0.0, 0.5 * a, a, 1.5 * a};
  double worst = 0.0;
  for (double z : {0.5 * h, h, h + 0.5 * a}) {
    const auto fine = axisymmetric_stress_at(body, AxisymmetricLoad::hertz, p0, a, r, z,
                                             InterfaceSide::below, 1e-12);
    const auto coarse = axisymmetric_stress_at(body, AxisymmetricLoad::hertz, p0, a, r, z,
                                               InterfaceSide::below, rel_tol);
    for (std::size_t k = 0; k < r.size(); ++k)
      worst = std::max(
          {worst, std::abs(fine[k].srr - coarse[k].srr), std::abs(fine[k].stt - coarse[k].stt),
           std::abs(fine[k].szz - coarse[k].szz), std::abs(fine[k].srz - coarse[k].srz)});
  }
  return worst;
}

std::string section_reference() {
  const auto cases = coated_cases();
  std::ostringstream md;
  md << "\n## The Hankel reference's convergence\n\n"
     << "Largest change / p0 of sigma_rr, sigma_tt, sigma_zz, tau_rz of the reference "
        "(validation/axisymmetric_stress.hpp) at its tolerance rel_tol against rel_tol = 1e-12, at "
        "r = 0, a/2, a, 3a/2 on the planes z = h/2, h, h + a/2 (the tables above use 1e-10).\n\n"
     << "| body | 1e-6 | 1e-8 | 1e-10 |\n|---|---|---|---|\n";
  for (const CoatedCase* c : {&cases[0], &cases[3]}) {
    md << "| " << c->label;
    for (double tol : {1e-6, 1e-8, 1e-10})
      md << " | " << format_number("%.1e", reference_change(c->body, c->h, tol));
    md << " |\n";
  }
  return md.str();
}

// Periodic stresses (periodic = true) under p0 cos(k x) and q0 cos(k x) on steel, two waves over
// 32 cells: the largest error of every component against Johnson's closed form of the cell-wise
// load's mode (amplitude sinc(k dx/2)), on planes 1 to 5 cells deep.
double sinusoid_error(double z_cells, bool shear) {
  const Grid g(32, 4, 1e-3, 0.125e-3);
  const double k = 4 * M_PI / g.lx(), nu = 0.3, s = std::sin(0.5 * k * g.dx()) / (0.5 * k * g.dx());
  Field load(g.nx(), g.ny());
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) load(i, j) = p0 * std::cos(k * g.x(i));
  StressOperatorOptions o;
  o.boundary = Boundary::periodic;
  o.tangential = shear;
  std::vector<PlaneStress> out;
  const Field zero = Field::Zero(g.nx(), g.ny());
  make_stress_operator(g, LayerStack(Material(210e9, nu)), {z_cells * g.dx()}, o)
      ->apply(shear ? zero : load, shear ? &load : nullptr, nullptr, out);
  double err = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
      const auto ref = sinusoidal_stress(k, shear ? 0.0 : s * p0, shear ? s * p0 : 0.0, nu, g.x(i),
                                         z_cells * g.dx());
      for (int c = 0; c < 6; ++c) err = std::max(err, std::abs(out[0][c](i, j) - ref[c]));
    }
  return err;
}

// A Hertz pressure (radius a, 8 cells per radius) in a period of L: the largest difference of the
// six stresses under its centre, on the planes z = a/2 and a, between the periodic and the free
// surface (the images' share).
double period_difference(int cells) {
  const Grid g(cells, cells, cells * a / 8, cells * a / 8);
  const Field p = hertz_pressure(g, p0, a, Sampling::cell_average);
  const std::vector<double> depths{0.5 * a, a};
  const LayerStack steel(Material(210e9, 0.3));
  StressOperatorOptions o;
  o.boundary = Boundary::periodic;
  std::vector<PlaneStress> periodic, free;
  make_stress_operator(g, steel, depths, o)->apply(p, nullptr, nullptr, periodic);
  free = stresses(g, steel, p, nullptr, depths);
  const std::ptrdiff_t c = g.centre_i();
  double diff = 0.0;
  for (std::size_t d = 0; d < depths.size(); ++d)
    for (int k = 0; k < 6; ++k)
      diff = std::max(diff, std::abs(periodic[d][k](c, c) - free[d][k](c, c)));
  return diff;
}

std::string section_periodic() {
  std::ostringstream md;
  md << "\n## Periodic surfaces\n\n"
     << "`[grid] boundary = \"periodic\"`: the planes' spectra on the period's lattice "
        "(docs/stress.md, \"Periodic surfaces\"). Sinusoidal pressure p0 cos(k x) and traction "
        "q0 cos(k x) on steel, two waves over 32 cells, against Johnson's (1985, 2.5) plane-strain "
        "closed form of the cell-wise load's mode (amplitude sinc(k dx/2)): the largest error "
        "/ p0 over the plane and the six components. Closer than three cells the load's aliases "
        "(its steps) reach the plane: the closed form is then not the reference.\n\n"
     << "| load | z = 1 dx | 2 dx | 3 dx | 5 dx |\n|---|---|---|---|---|\n";
  for (bool shear : {false, true}) {
    md << (shear ? "| traction q_x" : "| pressure");
    for (double z : {1.0, 2.0, 3.0, 5.0})
      md << " | " << format_number("%.1e", sinusoid_error(z, shear));
    md << " |\n";
  }
  md << "\nA Hertz pressure (a, dx = a/8) in periods L = 4a, 8a, 16a against the free surface: "
        "the largest difference / p0 of the six stresses under its centre at z = a/2 and a. "
        "The periodic images, a mean pressure (2 pi/3)(a/L)^2 p0 outside a hole about L wide, "
        "contribute about that times z/L there: the difference falls like L^-3.\n\n"
     << "| L | 4a | 8a | 16a |\n|---|---|---|---|\n| difference";
  for (int cells : {32, 64, 128}) md << " | " << format_number("%.1e", period_difference(cells));
  md << " |\n";
  return md.str();
}

int check() {
  tables::Checks checks("stress_table");
  const auto h = row_errors(grid_for(16), LayerStack(Material(210e9, 0.3)), AxisymmetricLoad::hertz,
                            {0.25 * a, a});
  for (double e : h) checks.expect(e < 2e-3, "homogeneous Hertz a/16", format_number("%.2e", e));
  for (double e : hamilton_errors(16, 0.25, {0.5 * a}))
    checks.expect(e < 1.2e-3, "sliding Hertz a/16 z = a/2", format_number("%.2e", e));
  const auto cases = coated_cases();
  for (const CoatedCase* c : {&cases[1], &cases[5]}) {
    const auto e = row_errors(grid_for(16), c->body, AxisymmetricLoad::hertz, coated_depths(*c));
    for (double v : e) checks.expect(v < 1.2e-3, c->label, format_number("%.2e", v));
  }
  // The frictionless interface carries no shear (case 5: E1/E2 = 0.1, h = a, frictionless).
  const Grid g = grid_for(16);
  const auto s =
      stresses(g, cases[5].body, load_on(g, AxisymmetricLoad::hertz), nullptr, {cases[5].h});
  const double shear = std::max(s[0][s_xz].abs().maxCoeff(), s[0][s_yz].abs().maxCoeff());
  checks.expect(shear < 1e-12, "frictionless interface shear", format_number("%.2e", shear));
  return checks.finish();
}

int write_table(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream md;
  md << "# Validation: stresses inside the body\n\n"
     << "Generated by `stress_table` (tables/stress_table.cpp; `scripts/make_validation_docs.sh`"
        " runs it). The stresses of StressOperator on planes z = const (docs/stress.md) against "
        "independent references. Grids of cell a/m with N = 4m + 1 cells a side (the origin a "
        "cell centre, the domain [-2a, 2a]^2 and a bit), cell-averaged loads.\n"
     << section_max_shear() << section_homogeneous() << section_alpha() << section_sliding()
     << section_coated(32) << section_hard() << section_reference() << section_periodic();
  return tables::write_table_file(output, md.str(), start);
}

}  // namespace

int main(int argc, char** argv) {
  return tables::table_main(
      argc, argv,
      {"stress_table", "Stresses inside the body against independent references",
       "docs/validation/stress.md", check, write_table});
}
