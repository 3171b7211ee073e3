// Validation of the surface displacements under tangential tractions (convolution/
// cerruti_operator.hpp, the 3 x 3 surface response of any bonded layer stack) and of the sliding
// contact built on them (contact/sliding_contact.hpp):
//  - the homogeneous half-space against closed forms: the Hertz-type traction
//    q_x = q0 sqrt(1 - r^2/a^2) (Johnson 1985, section 3.6) inside the contact and Cerruti's (1882)
//    uniformly sheared disk at its centre;
//  - coated bodies against the continuous Hankel reference of the same displacements
//    (validation/axisymmetric_traction.hpp), under the Hertz traction and the Hertz pressure;
//  - a coating of the substrate's own material against the homogeneous closed forms;
//  - hard bodies: a thick soft and a nearly incompressible coating, and the refusal of a coating
//    too thin for the traction kernels' lattices;
//  - the sliding Hertz contact, whose pressure the tractions' normal displacement shifts by an
//    amount of order beta mu (Johnson 1985, section 7.2).
// Loads are cell averages (exact cell forces) on grids of cell a/m with N = 4m + 1 cells a side
// (the origin a cell centre), so the error left is the piecewise-constant load's plus the
// kernels'. Writes docs/validation/traction.md.
//
// --check, at the tolerances of the measured values: at a/16 the half-space within 2e-3 u_x(0) of
// Johnson (1.4e-3 measured) and the disk's centre within 7e-4 of Cerruti (3.4e-4; the Hankel
// reference equal to Cerruti within 1e-9); a steel coating on steel equal to steel's closed forms
// within 1e-12 (6e-16); against the Hankel reference at a/16 under q_x and under p, the coating
// E1/E2 = 10, h = a within 1.5e-3 (7.7e-4), E1/E2 = 0.1, h = 0.1a within 8e-3 (6.2e-3), the
// nu = 0.4999 coating within 1e-2 (7.2e-3), every value finite; the stiff thick coating's lattice
// images at (2a, 0) at alpha = 16 (u_z under q_x there against alpha = 32) within 1.5e-4 u_x(0)
// (7e-5; 2.5e-4 before the remainders' k -> 0 limit was taken in closed form); the thin stiff
// coating refused with InvalidArgument; the sliding steel contact at mu = 0.25 converged with a
// pressure shift between 0.3 and 3 times beta mu (2.1 times on these 65^2 cells; it grows as
// finer cells resolve the contact's rim), its centroid moved backwards and the shift at mu = 0.5
// twice that at 0.25 within 5 % (0.6 %: a first-order effect).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <future>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/indenter.hpp"
#include "contact/sliding_contact.hpp"
#include "convolution/kernels/periodic_traction_kernels.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "tables/format_number.hpp"
#include "tables/table_program.hpp"
#include "validation/aliased_traction.hpp"
#include "validation/axisymmetric_traction.hpp"
#include "validation/hertz_contact.hpp"

namespace {

using namespace coatfft;
using tables::format_number;

constexpr double a = 1e-3;        // load radius [m]
constexpr double q0 = 1.0;        // Pa: displacements then in m/Pa
constexpr int kThreads = 2;       // lattice loops and the reference's points
constexpr double kRelTol = 1e-9;  // of the Hankel reference: far below the errors measured
const Material kSubstrate(1e11, 0.3);

Grid grid_for(int m) {
  const int n = 4 * m + 1;
  return {n, n, n * a / m, n * a / m};
}

// alpha: the period of the remainders' long-range lattice over the domain (LatticeOptions).
TractionKernelOptions kernel_options(int alpha = LatticeOptions{}.alpha) {
  TractionKernelOptions o;
  o.lattice.threads = kThreads;
  o.lattice.alpha = alpha;
  return o;
}

Field hertz_load(const Grid& g) {
  return hertz_pressure(g, q0, a, Sampling::cell_average);
}

std::string sci(double v) {
  return format_number("%.2e", v);
}

// The displacements of one body under the Hertz pressure and the Hertz traction q_x.
struct Response {
  std::array<Field, 3> under_p, under_qx;
  TractionKernelReport report;
  bool finite = false;
};

Response response_of(const Grid& g, const LayerStack& body, int alpha = LatticeOptions{}.alpha) {
  Response r;
  CerrutiOperator op(g, body, kernel_options(alpha), Planning::estimate, &r.report);
  const Field load = hertz_load(g);
  const Field zero = Field::Zero(g.nx(), g.ny());
  op.apply(load, nullptr, nullptr, r.under_p);
  op.apply(zero, &load, nullptr, r.under_qx);
  r.finite = true;
  for (const auto* u : {&r.under_p, &r.under_qx})
    for (const Field& f : *u) r.finite = r.finite && f.allFinite();
  return r;
}

}  // namespace

namespace {

// The comparison points: a lattice of spacing a/4 on the quadrant x, y >= 0 out to the domain's
// edge at 2a. The load is symmetric and each kernel has a definite parity, so the other
// quadrants repeat these errors; points 0 < r < 0.2a are skipped, where the reference's
// quadrature range grows like a/r.
struct Point {
  int k, l;  // x = k a/4, y = l a/4
  double x() const { return k * a / 4; }
  double y() const { return l * a / 4; }
};

std::vector<Point> sample_points() {
  std::vector<Point> points;
  for (int l = 0; l <= 8; ++l)
    for (int k = 0; k <= 8; ++k) {
      const double r = std::hypot(k, l) / 4;
      if (r == 0 || r >= 0.2) points.push_back({k, l});
    }
  return points;
}

// The Hankel reference at every point, the points shared out among kThreads threads (the
// reference is safe to call concurrently).
std::vector<SurfaceDisplacement> reference(const LayerStack& body, LoadDirection direction,
                                           const std::vector<Point>& points) {
  std::vector<SurfaceDisplacement> u(points.size());
  const auto work = [&](std::size_t first) {
    for (std::size_t n = first; n < points.size(); n += kThreads)
      u[n] = axisymmetric_surface_displacement(body, AxisymmetricLoad::hertz, direction, q0, a,
                                               points[n].x(), points[n].y(), kRelTol);
  };
  std::vector<std::future<void>> others;
  for (int t = 1; t < kThreads; ++t) others.push_back(std::async(std::launch::async, work, t));
  work(0);
  for (auto& f : others) f.get();
  return u;
}

// Largest |u - u_ref| of the three components over the points, over `scale`.
double max_error(const Grid& g, int m, const std::array<Field, 3>& u,
                 const std::vector<SurfaceDisplacement>& ref, const std::vector<Point>& points,
                 double scale) {
  const std::ptrdiff_t c = g.centre_i(), step = m / 4;
  double e = 0.0;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const std::ptrdiff_t i = c + points[n].k * step, j = c + points[n].l * step;
    e = std::max({e, std::abs(u[0](i, j) - ref[n].ux), std::abs(u[1](i, j) - ref[n].uy),
                  std::abs(u[2](i, j) - ref[n].uz)});
  }
  return e / scale;
}

// A body's references under q_x and p (computed once, shared by every grid).
struct BodyReference {
  std::vector<SurfaceDisplacement> qx, p;
  double qx_scale, p_scale;  // |u_x(0)| under q_x, |u_z(0)| under p
};

BodyReference body_reference(const LayerStack& body, const std::vector<Point>& points) {
  BodyReference r{reference(body, LoadDirection::traction_x, points),
                  reference(body, LoadDirection::pressure, points), 0.0, 0.0};
  r.qx_scale = std::abs(r.qx.front().ux);  // points.front() is the origin
  r.p_scale = std::abs(r.p.front().uz);
  return r;
}

struct ErrorRow {
  double qx, p;  // largest error under q_x over |u_x(0)|, under p over |u_z(0)|
  TractionKernelReport report;
  bool finite;
};

ErrorRow error_row(int m, const LayerStack& body, const BodyReference& ref,
                   const std::vector<Point>& points, int alpha = LatticeOptions{}.alpha) {
  const Grid g = grid_for(m);
  const Response r = response_of(g, body, alpha);
  return {max_error(g, m, r.under_qx, ref.qx, points, ref.qx_scale),
          max_error(g, m, r.under_p, ref.p, points, ref.p_scale), r.report, r.finite};
}

}  // namespace

namespace {

// Johnson (1985), section 3.6: (u_x, u_y) inside r <= a under q_x = q0 sqrt(1 - r^2/a^2) on a
// half-space of shear modulus G and Poisson ratio nu.
std::array<double, 2> johnson_traction(double x, double y, double nu, double G) {
  const double f = std::numbers::pi * q0 / (32 * G * a);
  return {f * (4 * (2 - nu) * a * a - (4 - 3 * nu) * x * x - (4 - nu) * y * y), f * 2 * nu * x * y};
}

// Largest |error| of u_x, u_y over every cell centre inside r <= a, over Johnson's u_x(0).
double johnson_error(int m) {
  const Grid g = grid_for(m);
  const Response r = response_of(g, LayerStack(kSubstrate));
  const double nu = kSubstrate.poisson_ratio(), G = kSubstrate.shear_modulus();
  double e = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i) {
      if (std::hypot(g.x(i), g.y(j)) > a) continue;
      const auto [ux, uy] = johnson_traction(g.x(i), g.y(j), nu, G);
      e = std::max({e, std::abs(r.under_qx[0](i, j) - ux), std::abs(r.under_qx[1](i, j) - uy)});
    }
  return e / johnson_traction(0, 0, nu, G)[0];
}

// Cerruti (1882): u_x(0) = (2 - nu) q c/(2 G) at the centre of a disk of radius c under a
// uniform q_x. The operator's value on the cell-averaged disk, over the closed form, minus 1.
double cerruti_disk_error(int m) {
  const Grid g = grid_for(m);
  CerrutiOperator op(g, kSubstrate);
  const Field disk = uniform_disk_pressure(g, q0, a, Sampling::cell_average);
  std::array<Field, 3> u;
  op.apply(Field::Zero(g.nx(), g.ny()), &disk, nullptr, u);
  const double nu = kSubstrate.poisson_ratio();
  const double closed = (2 - nu) * q0 * a / (2 * kSubstrate.shear_modulus());
  return u[0](g.centre_i(), g.centre_j()) / closed - 1;
}

// The Hankel reference of the same disk centre over Cerruti's closed form, minus 1.
double cerruti_reference_difference() {
  const double nu = kSubstrate.poisson_ratio();
  const double closed = (2 - nu) * q0 * a / (2 * kSubstrate.shear_modulus());
  const SurfaceDisplacement u =
      axisymmetric_surface_displacement(LayerStack(kSubstrate), AxisymmetricLoad::uniform_disk,
                                        LoadDirection::traction_x, q0, a, 0.0, 0.0, 1e-12);
  return u.ux / closed - 1;
}

std::string order(double coarse, double fine) {
  return format_number("%.2f", std::log2(coarse / fine));
}

std::string section_half_space() {
  std::ostringstream md;
  md << "\n## Homogeneous half-space: closed forms\n\n"
     << "nu = 0.3. Hertz-type traction q_x = q0 sqrt(1 - r^2/a^2): largest |error| of u_x, u_y "
        "over every cell centre inside r <= a against Johnson (1985), section 3.6: u_x = "
        "(pi q0/(32 G a)) [4(2 - nu) a^2 - (4 - 3 nu) x^2 - (4 - nu) y^2], u_y = "
        "(pi q0/(32 G a)) 2 nu x y, over u_x(0). Uniform q on a disk of radius c = a: u_x at "
        "its centre against Cerruti's (1882) (2 - nu) q c/(2 G), relative.\n\n"
     << "| dx | Hertz traction: error / u_x(0) | order | uniform disk: u_x(0) / closed form - 1 "
        "|\n|---|---|---|---|\n";
  double previous = 0.0;
  for (int m : {8, 16, 32, 64}) {
    const double e = johnson_error(m);
    md << "| a/" << m << " | " << sci(e) << " | " << (m == 8 ? "" : order(previous, e)) << " | "
       << format_number("%+.2e", cerruti_disk_error(m)) << " |\n";
    previous = e;
  }
  md << "\nThe Hankel reference of the disk's centre (validation/axisymmetric_traction.hpp, "
        "rel_tol 1e-12) differs from Cerruti's closed form by "
     << format_number("%+.1e", cerruti_reference_difference())
     << " (relative): the closed form is the reference of the last column.\n";
  return md.str();
}

}  // namespace

namespace {

struct Body {
  std::string label;
  LayerStack stack;
};

// In coated_bodies(): the thin soft coating and the stiff thick one.
constexpr std::size_t kThinSoft = 1, kStiffThick = 4;

std::vector<Body> coated_bodies() {
  std::vector<Body> bodies{{"homogeneous, nu = 0.3", LayerStack(kSubstrate)}};
  for (double ratio : {0.1, 10.0})
    for (double h : {0.1, 1.0}) {
      std::ostringstream label;
      label << "E1/E2 = " << ratio << ", h/a = " << h;
      bodies.push_back(
          {label.str(),
           LayerStack({{Material(ratio * 1e11, 0.25), h * a, Interface::bonded}}, kSubstrate)});
    }
  bodies.push_back({"two coatings: E 200 GPa, h 0.1a over E 50 GPa, h 0.2a",
                    LayerStack({{Material(2e11, 0.25), 0.1 * a, Interface::bonded},
                                {Material(0.5e11, 0.25), 0.2 * a, Interface::bonded}},
                               kSubstrate)});
  return bodies;
}

// The table cells "setup [s] | lattice evaluations".
std::string setup_cells(const TractionKernelReport& r) {
  return format_number("%.2f", r.seconds) + " | " + std::to_string(r.lattice.evaluations);
}

// The stiff thick coating at a/64 against the lattice's period alpha: what the lattice carries,
// the remainders less their k -> 0 limit (taken in closed form, docs/theory.md (2.9.6)), has
// tails ~ cos(n theta)/r^3 whose periodic images fall like alpha^-4. The far point (2a, 0) shows
// them apart from the load's discretisation, which is largest near r = a.
std::string alpha_study(const Body& body, const BodyReference& ref,
                        const std::vector<Point>& points) {
  const auto far = static_cast<std::size_t>(
      std::find_if(points.begin(), points.end(), [](Point q) { return q.k == 8 && q.l == 0; }) -
      points.begin());
  std::ostringstream md;
  md << "\nThe same errors for " << body.label
     << " at a/64 against the period alpha of the remainders' long-range lattice (LatticeOptions::"
        "alpha; the default is "
     << LatticeOptions{}.alpha
     << "), and the error of u_z under q_x at (2a, 0) over |u_x(0)|. The remainders of the "
        "angular FRFs tend to nonzero constants times cos(n theta) as k -> 0; their limits are "
        "taken in closed form (docs/theory.md (2.9.6)), so that the lattice carries tails "
        "~ cos(n theta)/r^3 only, whose periodic images fall like alpha^-4 (left on the lattice, "
        "the limit's cos(theta)/r^2 tail gave 2.5e-4 at alpha = 16).\n\n"
     << "| alpha | setup [s] | lattice evaluations | under q_x | under p | u_z(2a, 0) under q_x "
        "|\n|---|---|---|---|---|---|\n";
  const Grid g = grid_for(64);
  for (int alpha : {8, 16, 32, 64}) {
    const Response r = response_of(g, body.stack, alpha);
    const double u = r.under_qx[2](g.centre_i() + 2 * 64, g.centre_j());
    md << "| " << alpha << " | " << setup_cells(r.report) << " | "
       << sci(max_error(g, 64, r.under_qx, ref.qx, points, ref.qx_scale)) << " | "
       << sci(max_error(g, 64, r.under_p, ref.p, points, ref.p_scale)) << " | "
       << sci(std::abs(u - ref.qx[far].uz) / ref.qx_scale) << " |\n";
  }
  return md.str();
}

std::string section_coated() {
  const std::vector<Point> points = sample_points();
  const std::vector<Body> bodies = coated_bodies();
  std::ostringstream md;
  md << "\n## Coated bodies against the Hankel reference\n\n"
     << "Substrate E2 = 100 GPa, nu 0.3; coatings nu 0.25, bonded. Largest |error| of (u_x, u_y, "
        "u_z) over the lattice of spacing a/4 on x, y >= 0 out to 2a ("
     << points.size()
     << " points; the other quadrants repeat them by symmetry) against "
        "axisymmetric_surface_displacement: under the Hertz traction q_x over |u_x(0)|, under "
        "the Hertz pressure over |u_z(0)|. Setup: the traction kernels' wall time "
        "(TractionKernelReport::seconds, "
     << kThreads
     << " threads) and the FRF evaluations of their remainders' lattices (0: closed "
        "forms). Order: log2 of the error at the coarser grid over this one's (under q_x, under "
        "p).\n\n"
     << "| body | dx | setup [s] | lattice evaluations | under q_x | under p | order "
        "|\n|---|---|---|---|---|---|---|\n";
  std::vector<BodyReference> refs;
  std::vector<std::string> stalled;  // order below 1 from a/32 to a/64
  for (const Body& b : bodies) {
    refs.push_back(body_reference(b.stack, points));
    std::optional<ErrorRow> coarser;
    for (int m : {16, 32, 64}) {
      const ErrorRow r = error_row(m, b.stack, refs.back(), points);
      md << "| " << (coarser ? "" : b.label) << " | a/" << m << " | " << setup_cells(r.report)
         << " | " << sci(r.qx) << " | " << sci(r.p) << " | "
         << (coarser ? order(coarser->qx, r.qx) + ", " + order(coarser->p, r.p) : "") << " |\n";
      if (m == 64 && std::min(coarser->qx / r.qx, coarser->p / r.p) < 2.0)
        stalled.push_back(b.label);
      coarser = r;
    }
  }
  md << "\nThe coated bodies' errors fall at the homogeneous body's rate (the rate of the "
        "half-space's closed-form kernels in the first table): what is left is the "
        "piecewise-constant load's error, which a thin soft coating, whose surface follows the "
        "load more closely, shows more of.";
  for (std::size_t n = 0; n < stalled.size(); ++n)
    md << (n == 0 ? " From a/32 to a/64 the error of " : "; of ") << stalled[n];
  if (!stalled.empty())
    md << " no longer halves: the periodic images of the coupling kernel's lattice (next table).";
  md << "\n" << alpha_study(bodies[kStiffThick], refs[kStiffThick], points);
  return md.str();
}

}  // namespace

namespace {

// A steel coating on steel, against steel's closed forms: the largest difference of the three
// components over the largest component, under p, q_x and q_y in turn.
std::array<double, 3> same_material_differences() {
  const Material steel(210e9, 0.3);
  const Grid g = grid_for(16);  // 65^2 cells
  CerrutiOperator layered(g, LayerStack({{steel, 0.1 * a, Interface::bonded}}, steel),
                          kernel_options());
  CerrutiOperator closed(g, steel);
  const Field load = hertz_load(g), zero = Field::Zero(g.nx(), g.ny());
  std::array<double, 3> differences{};
  for (int d = 0; d < 3; ++d) {
    const Field* p = d == 0 ? &load : &zero;
    const Field* qx = d == 1 ? &load : nullptr;
    const Field* qy = d == 2 ? &load : nullptr;
    std::array<Field, 3> u, v;
    layered.apply(*p, qx, qy, u);
    closed.apply(*p, qx, qy, v);
    double diff = 0.0, size = 0.0;
    for (int c = 0; c < 3; ++c) {
      diff = std::max(diff, (u[c] - v[c]).abs().maxCoeff());
      size = std::max(size, v[c].abs().maxCoeff());
    }
    differences[d] = diff / size;
  }
  return differences;
}

std::string section_same_material() {
  const auto d = same_material_differences();
  std::ostringstream md;
  md << "\n## Coating = substrate\n\n"
     << "A steel coating (h = 0.1a, E = 210 GPa, nu 0.3) on steel, through the layered route "
        "(the split and the lattices), against steel's closed forms (Love 1929, Cerruti 1882) "
        "on the 65^2 grid of dx = a/16, Hertz-shaped loads: the largest difference of u_x, u_y, "
        "u_z over the largest displacement.\n\n"
     << "| load | relative difference |\n|---|---|\n"
     << "| p | " << sci(d[0]) << " |\n| q_x | " << sci(d[1]) << " |\n| q_y | " << sci(d[2])
     << " |\n";
  return md.str();
}

// A coating too thin for the traction kernels' lattices on a 65^2 grid over 4a.
const Grid kThinGrid(65, 65, 4 * a, 4 * a);

LayerStack thin_stiff() {
  return LayerStack({{Material(1e13, 0.25), 1e-3 * a, Interface::bonded}}, kSubstrate);
}

// The refusal's message, or nothing when it was not refused.
std::optional<std::string> thin_stiff_refusal() {
  try {
    CerrutiOperator op(kThinGrid, thin_stiff(), kernel_options());
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return std::nullopt;
}

std::vector<Body> hard_bodies() {
  return {{"thick soft: h/a = 50, E1/E2 = 0.01",
           LayerStack({{Material(1e9, 0.25), 50 * a, Interface::bonded}}, kSubstrate)},
          {"nu = 0.4999 coating: h/a = 0.1, E1/E2 = 0.1",
           LayerStack({{Material(1e10, 0.4999), 0.1 * a, Interface::bonded}}, kSubstrate)}};
}

std::string section_hard() {
  const std::vector<Point> points = sample_points();
  std::ostringstream md;
  md << "\n## Hard bodies at dx = a/16\n\n"
     << "Errors as in the coated bodies' table (bonded coatings on the same substrate).\n\n"
     << "| body | setup [s] | lattice evaluations | every value finite | under q_x | under p "
        "|\n|---|---|---|---|---|---|\n";
  for (const Body& b : hard_bodies()) {
    const ErrorRow r = error_row(16, b.stack, body_reference(b.stack, points), points);
    md << "| " << b.label << " | " << setup_cells(r.report) << " | "
       << (r.finite ? "yes" : "**no**") << " | " << sci(r.qx) << " | " << sci(r.p) << " |\n";
  }
  const auto refusal = thin_stiff_refusal();
  md << "\nA thin stiff coating, h/a = 1e-3, E1/E2 = 100, on a 65^2 grid over 4a: its "
        "remainders decay only beyond k ~ 1/h, so their lattice needs about "
     << sci(traction_kernel_evaluations(kThinGrid, thin_stiff(), kernel_options()))
     << " FRF evaluations (the limit, LatticeOptions::max_evaluations: "
     << sci(kernel_options().lattice.max_evaluations) << "). "
     << (refusal ? "It is refused before any work, a documented limit:\n\n> " + *refusal + "\n"
                 : std::string("**It was not refused.**\n"));
  return md.str();
}

}  // namespace

namespace {

// The sliding Hertz contact: a rigid paraboloid R = 10 mm on the body, the load giving a = 0.3 mm
// on bare steel, on 65^2 cells over 4a.
constexpr double kRadius = 0.01;
constexpr double kContactRadius = 3e-4;
const Material kSteel(210e9, 0.3);

double sliding_load() {
  return hertz_sphere_for_approach(kContactRadius * kContactRadius / kRadius, kRadius,
                                   kSteel.plane_strain_modulus())
      .load;
}

struct SlidingRow {
  double mu;
  SlidingReport report;
  double centroid;  // x of the pressure's centroid over a
};

double centroid(const Grid& g, const Field& p) {
  double moment = 0.0;
  for (std::ptrdiff_t i = 0; i < g.nx(); ++i) moment += g.x(i) * p.row(i).sum();
  return moment / p.sum() / kContactRadius;
}

// One contact per friction coefficient on `body`: the normal operator of make_operator (Love's
// DC-FFT, or frf-split for a coated body) and the coupling u_z under q_x = mu p of
// make_tangential_operator, as the command line builds them (scene/scene_run.cpp); n^2 cells
// over 4a.
std::vector<SlidingRow> sliding_rows(const LayerStack& body, const std::vector<double>& mus,
                                     std::ptrdiff_t n = 65) {
  const Grid g(n, n, 4 * kContactRadius, 4 * kContactRadius);
  OperatorOptions options;
  options.method = exact_method(body);
  options.threads = kThreads;
  const BuiltOperator normal = make_operator(g, body, options);
  ContactSolver solver(*normal.op);
  TangentialOptions tangential_options;
  tangential_options.threads = kThreads;
  const BuiltTangentialOperator built = make_tangential_operator(g, body, tangential_options);
  CerrutiOperator& tangential = *built.op;
  const TangentialCoupling coupling = [&](const Field& qx) {
    std::array<Field, 3> u;
    tangential.apply(Field::Zero(g.nx(), g.ny()), &qx, nullptr, u);
    return u[2];
  };
  const Field h = height(g, Paraboloid{kRadius});
  std::vector<SlidingRow> rows;
  for (double mu : mus) {
    SlidingOptions o;
    o.friction = mu;
    SlidingRow row{mu, {}, 0.0};
    const ContactResult res =
        solve_sliding(solver, coupling, h, ContactControl::load, sliding_load(), o, &row.report);
    COATFFT_REQUIRE(!res.touches_boundary, "sliding contact reaches the domain edge");
    row.centroid = centroid(g, res.pressure);
    rows.push_back(row);
  }
  return rows;
}

double beta(const Material& m) {
  const double nu = m.poisson_ratio();
  return (1 - 2 * nu) / (2 * (1 - nu));
}

}  // namespace

namespace {

std::string sliding_table(const std::string& label, const LayerStack& body, const Material& top) {
  std::ostringstream md;
  const auto rows = sliding_rows(body, {0.0, 0.1, 0.25, 0.5});
  md << "\n"
     << label << " (beta = " << format_number("%.4f", beta(top)) << "):\n\n"
     << "| mu | solves | converged | pressure_shift | beta mu | centroid shift / a |\n"
        "|---|---|---|---|---|---|\n";
  for (const SlidingRow& r : rows)
    md << "| " << r.mu << " | " << r.report.solves << " | " << (r.report.converged ? "yes" : "no")
       << " | " << sci(r.report.pressure_shift) << " | " << sci(beta(top) * r.mu) << " | "
       << format_number("%+.2e", r.centroid - rows.front().centroid) << " |\n";
  return md.str();
}

// pressure_shift is set by the contact's rim, where the square-root edge of the pressure moves
// with the contact: a shift e of the edge changes p there by about p0 sqrt(2 e/a), which the
// cells resolve only as they shrink. The centroid is an integral and does not depend on them.
std::string sliding_grids() {
  std::ostringstream md;
  md << "\nSteel at mu = 0.25 as the grid is refined: pressure_shift grows with the resolution of "
        "the contact's rim, where the square-root edge of the pressure moves with the contact (a "
        "shift e of the edge changes p by about p0 sqrt(2 e/a) there); the centroid shift, an "
        "integral, does not depend on the grid.\n\n"
     << "| cells | dx / a | solves | pressure_shift | centroid shift / a "
        "|\n|---|---|---|---|---|\n";
  for (std::ptrdiff_t n : {65, 129, 257}) {
    const auto rows = sliding_rows(LayerStack(kSteel), {0.0, 0.25}, n);
    md << "| " << n << "^2 | " << format_number("%.4f", 4.0 / static_cast<double>(n)) << " | "
       << rows[1].report.solves << " | " << sci(rows[1].report.pressure_shift) << " | "
       << format_number("%+.3e", rows[1].centroid - rows[0].centroid) << " |\n";
  }
  return md.str();
}

LayerStack tin_on_steel() {
  return LayerStack({{Material(400e9, 0.25), 0.1 * kContactRadius, Interface::bonded}}, kSteel);
}

std::string section_sliding() {
  std::ostringstream md;
  md << "\n## Sliding Hertz contact\n\n"
     << "A rigid paraboloid R = 10 mm slides along +x under the load W = "
     << format_number("%.1f", sliding_load())
     << " N (Hertz a = 0.3 mm on bare steel), 65^2 cells over 4a; full sliding, q_x = mu p. "
        "solve_sliding iterates the normal solve with the tractions' normal displacement "
        "(u_z under q_x of CerrutiOperator) to its fixed point (tolerance "
     << format_number("%.0e", SlidingOptions{}.tolerance)
     << "). pressure_shift: max |p - p_frictionless| / max p_frictionless; centroid shift: the "
        "pressure's centroid along x against the frictionless one, over a = 0.3 mm. Johnson "
        "(1985), section 7.2: the tractions' effect on the pressure is of order beta mu, beta = "
        "(1 - 2 nu)/(2 (1 - nu)) of the body (for the coated body, of the coating). The "
        "tractions sink the surface ahead of them and raise it behind (Betti's reciprocity: the "
        "surface moves toward a normal force, Boussinesq's solution), so the pressure moves "
        "toward the trailing edge, x < 0.\n"
     << sliding_table("Steel (E = 210 GPa, nu 0.3)", LayerStack(kSteel), kSteel)
     << sliding_table("TiN (E = 400 GPa, nu 0.25), h = 0.1a, bonded on steel", tin_on_steel(),
                      Material(400e9, 0.25))
     << sliding_grids();
  return md.str();
}

}  // namespace

namespace {

void check_sliding(tables::Checks& checks) {
  const auto rows = sliding_rows(LayerStack(kSteel), {0.0, 0.25, 0.5});
  const double bm = beta(kSteel) * 0.25;
  const SlidingRow& r = rows[1];
  checks.expect(r.report.converged, "sliding steel mu = 0.25", "not converged");
  checks.expect(r.report.pressure_shift > 0.3 * bm && r.report.pressure_shift < 3 * bm,
                "sliding steel mu = 0.25",
                "pressure_shift " + sci(r.report.pressure_shift) + ", beta mu " + sci(bm));
  const double c25 = rows[1].centroid - rows[0].centroid, c50 = rows[2].centroid - rows[0].centroid;
  checks.expect(c25 < 0 && std::abs(c50 / (2 * c25) - 1) < 0.05,
                "sliding steel centroid backwards, linear in mu",
                "shift " + sci(c25) + " at mu = 0.25, " + sci(c50) + " at mu = 0.5");
}

void check_half_space(tables::Checks& checks) {
  const double j = johnson_error(16);
  checks.expect(j < 2e-3, "half-space vs Johnson a/16", sci(j));
  const double disk = cerruti_disk_error(16);
  checks.expect(std::abs(disk) < 7e-4, "Cerruti disk a/16", sci(disk));
  const double hankel = cerruti_reference_difference();
  checks.expect(std::abs(hankel) < 1e-9, "Hankel reference vs Cerruti disk", sci(hankel));
  for (double d : same_material_differences())
    checks.expect(d < 1e-12, "coating = substrate", sci(d));
}

// The coated rows at a/16 against their tolerances, on the table's points along the x axis, the
// y axis and the diagonal, a/2 apart (the largest errors, near r = a, are among them: (a, 0),
// (0, a), (a/2, a/2) and (a, a) around the edge), and the stiff thick coating's lattice
// images at the far point (2a, 0) at the default alpha = 16: u_z under q_x there against
// alpha = 32, whose images are 15 times smaller (the table's alpha study).
void check_coated(tables::Checks& checks) {
  std::vector<Point> points;
  for (const Point& q : sample_points())
    if (q.k % 2 == 0 && q.l % 2 == 0 && (q.k == 0 || q.l == 0 || q.k == q.l)) points.push_back(q);
  const std::vector<Body> bodies = coated_bodies(), hard = hard_bodies();
  struct Case {
    const Body& body;
    double tolerance;
  };
  for (const Case& c :
       {Case{bodies[kStiffThick], 1.5e-3}, Case{bodies[kThinSoft], 8e-3}, Case{hard[1], 1e-2}}) {
    const ErrorRow r = error_row(16, c.body.stack, body_reference(c.body.stack, points), points);
    checks.expect(r.finite, c.body.label + ", a/16", "a value is not finite");
    checks.expect(r.qx < c.tolerance, c.body.label + ", a/16 under q_x", sci(r.qx));
    checks.expect(r.p < c.tolerance, c.body.label + ", a/16 under p", sci(r.p));
  }
  const LayerStack& stiff = bodies[kStiffThick].stack;
  const auto ref = reference(stiff, LoadDirection::traction_x, {{0, 0}});
  const Grid g = grid_for(16);
  const auto far_uz = [&](int alpha) {
    return response_of(g, stiff, alpha).under_qx[2](g.centre_i() + 32, g.centre_j());
  };
  const double images = std::abs(far_uz(16) - far_uz(32)) / std::abs(ref[0].ux);
  checks.expect(images < 1.5e-4, bodies[kStiffThick].label + " images at alpha = 16", sci(images));
}

// The discrete transform sum_d K(d) exp(-i k.d) of a periodic kernel at lattice point (m, n).
std::complex<double> lattice_transform(const Grid& g, const Field& k, int m, int n) {
  std::complex<double> s = 0.0;
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      s += k(i, j) * std::polar(1.0, -2.0 * std::numbers::pi *
                                         (double(m * i) / g.nx() + double(n * j) / g.ny()));
  return s;
}

// The periodic kernels of `body` against the alias series of their FRFs
// (validation/aliased_traction.hpp): the largest error over the six kernels / (S_inf dx), a cell's
// in-plane displacement per unit load, at lattice points along the axes (alternating series,
// summed to about 1e-11 of that) and at the oblique (2, 1) (the double series to |p|, |q| <= 400,
// converging like 1/P), with the kernels' setup time.
std::array<double, 3> periodic_errors(const Grid& g, const LayerStack& body) {
  const auto start = std::chrono::steady_clock::now();
  PeriodicKernelOptions options;
  options.threads = kThreads;
  const TractionKernels k = periodic_traction_kernels(g, body, options);
  const double seconds = detail::seconds_since(start);
  const TractionResponse r(body);
  const Field* fields[6] = {&k.zp, &k.xx, &k.yy, &k.yx, &k.zx, &k.zy};
  const double scale = r.at_infinity().s * g.dx();
  double axis = 0.0, oblique = 0.0;
  for (auto [m, n] :
       {std::pair{1, 0}, {5, 0}, {int(g.nx()) / 2 - 1, 0}, {0, 1}, {0, int(g.ny()) / 2 - 1}}) {
    const auto ref = aligned_alias_sum(g, r, m, n, 4000);
    for (int c = 0; c < 6; ++c)
      axis = std::max(axis, std::abs(lattice_transform(g, *fields[c], m, n) - ref[c]) / scale);
  }
  const auto ref = alias_sum(g, r, 2, 1, 400, 400);
  for (int c = 0; c < 6; ++c)
    oblique = std::max(oblique, std::abs(lattice_transform(g, *fields[c], 2, 1) - ref[c]) / scale);
  return {axis, oblique, seconds};
}

std::string section_periodic() {
  const Grid g(32, 24, 1e-3, 0.75e-3);
  const Material soft(0.1 * kSubstrate.youngs_modulus(), 0.3),
      stiff(10 * kSubstrate.youngs_modulus(), 0.3);
  const std::pair<std::string, LayerStack> bodies[] = {
      {"half-space", LayerStack(kSubstrate)},
      {"E1/E2 = 10, h = 2 dx", LayerStack({{stiff, 2 * g.dx()}}, kSubstrate)},
      {"E1/E2 = 0.1, h = 4 dx", LayerStack({{soft, 4 * g.dx()}}, kSubstrate)},
      {"E1/E2 = 10, h = dx/2", LayerStack({{stiff, 0.5 * g.dx()}}, kSubstrate)}};
  std::ostringstream md;
  md << "\n## Periodic surfaces\n\n"
     << "The periodic 3 x 3 response (`periodic_traction_kernels`, docs/theory.md 4.8) on 32 x 24 "
        "cells over 1 x 0.75 mm: each kernel's discrete transform at a lattice wavevector against "
        "the alias series of its FRF times the cell's transform "
        "(validation/aliased_traction.hpp), summed term by term; the largest error over the six "
        "kernels / (S_inf dx), a cell's in-plane displacement per unit load. Along the axes "
        "((1, 0), (5, 0), (15, 0), (0, 1), (0, 11)) the series alternates and is summed to about "
        "1e-11 of that; at the oblique (2, 1) the double series is cut at |p|, |q| <= 400 and "
        "converges like 1/400: its column is the reference's own error, not the kernels'.\n\n"
     << "| body | axes | oblique (2, 1) | setup |\n|---|---|---|---|\n";
  for (const auto& [label, body] : bodies) {
    const auto e = periodic_errors(g, body);
    md << "| " << label << " | " << format_number("%.1e", e[0]) << " | "
       << format_number("%.1e", e[1]) << " | " << format_number("%.2f", e[2]) << " s |\n";
  }
  return md.str();
}

int check() {
  tables::Checks checks("traction_table");
  check_half_space(checks);
  check_coated(checks);
  checks.expect(thin_stiff_refusal().has_value(), "thin stiff coating", "not refused");
  check_sliding(checks);
  return checks.finish();
}

int write_table(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream md;
  md << "# Validation: surface displacements under tangential tractions\n\n"
     << "Generated by `traction_table` (tables/traction_table.cpp; "
        "`scripts/make_validation_docs.sh` runs it). The surface displacements (u_x, u_y, u_z) "
        "of CerrutiOperator (convolution/operators/cerruti_operator.hpp) under a pressure p and a "
        "tangential traction q_x against closed forms and the continuous Hankel reference "
        "(validation/axisymmetric_traction.hpp), and the sliding contact built on them. Grids "
        "of cell a/m with N = 4m + 1 cells a side (the origin a cell centre, the domain "
        "[-2a, 2a]^2 and a bit), cell-averaged loads of radius a = 1 mm.\n"
     << section_half_space() << section_coated() << section_same_material() << section_hard()
     << section_sliding() << section_periodic();
  return tables::write_table_file(output, md.str(), start);
}

}  // namespace

int main(int argc, char** argv) {
  return tables::table_main(
      argc, argv,
      {"traction_table", "Surface displacements under tangential tractions against references",
       "docs/validation/traction.md", check, write_table});
}
