// The tangential problem of a partial-slip step (contact/detail/tangential_iteration.hpp): under a
// shift, a conjugate gradient whose slipping cells turn on their circles; under a load, the shift
// that carries it, found by a bracketing secant over those solves.
#include "contact/detail/tangential_iteration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "contact/detail/fourier_preconditioner.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft::detail {

namespace {

// |(x, y)| without std::hypot's care for overflow, which tractions [Pa] and slips [m] are far
// from, and which cost a quarter of an iteration's element-wise passes (measured).
inline double length(double x, double y) {
  return std::sqrt(x * x + y * y);
}

// Projects (qx, qy) cell by cell on the disks |q| <= bound (q = 0 where bound = 0).
void project_tractions(const Field& bound, Field& qx, Field& qy) {
  for (Eigen::Index k = 0; k < bound.size(); ++k) {
    const double n = length(qx(k), qy(k));
    const double scale = bound(k) <= 0.0 ? 0.0 : n <= bound(k) ? 1.0 : bound(k) / n;
    qx(k) *= scale;
    qy(k) *= scale;
  }
}

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

// The cells that stick: in contact, inside their disk (the projection leaves a saturated cell on
// its circle to rounding).
Mask sticking(const Field& bound, const Field& qx, const Field& qy) {
  Mask m(bound.rows(), bound.cols());
  for (Eigen::Index k = 0; k < bound.size(); ++k)
    m(k) = bound(k) > 0.0 && length(qx(k), qy(k)) < bound(k) * (1.0 - 1e-12);
  return m;
}

// The iterate: q, the relative in-plane displacement u under p and q, and the slip
// s = u - target - d e_x (d the shift's increment), zero off the contact.
struct Iterate {
  const TangentialProblem& problem;
  RelativeSurfaceResponse& response;
  Field qx, qy, ux, uy, sx, sy;
  int applications = 0;

  void displace() {
    std::array<Field, 3> u;
    response.apply_in_plane(problem.pressure, &qx, &qy, u);
    applications += response.applications_per_apply();
    ux = std::move(u[0]);
    uy = std::move(u[1]);
    const auto in = *problem.bound > 0.0;
    sx = in.select(ux - *problem.target_x - problem.value, 0.0);
    sy = in.select(uy - *problem.target_y, 0.0);
  }
};

// A cell's own compliance K_ii [m/Pa] (u_x of a cell under a unit q_x on itself), and the
// factor that makes the Fourier preconditioner P an approximate inverse of the response: P K ~
// `inverse_scale` times the identity, read from P (K e) at the loaded cell e (one application).
struct CellScales {
  double self_compliance;
  double inverse_scale;
};

CellScales cell_scales(RelativeSurfaceResponse& response, FourierPreconditioner& preconditioner,
                       int& applications) {
  const Grid& g = response.grid();
  Field unit = Field::Zero(g.nx(), g.ny());
  unit(g.centre_i(), g.centre_j()) = 1.0;
  std::array<Field, 3> u;
  response.apply_in_plane(nullptr, &unit, nullptr, u);
  applications += response.applications_per_apply();
  const double self = u[0](g.centre_i(), g.centre_j());
  preconditioner.apply(u[0]);
  return {self, u[0](g.centre_i(), g.centre_j())};
}

// The search's gradient g and its preconditioned form z, and the constraint's curvature c, per
// cell. A free cell -- one that sticks, or slips along its traction and so sticks again, as
// Polonsky & Keer (1999) return an overlapping cell to the contact -- moves freely: g = s, and z
// is the Fourier preconditioner's approximate inverse K^-1 g over the free cells (the normal
// iteration's, contact/detail/fourier_preconditioner.hpp: the in-plane compliance falls as 1/r at
// every scale too). A slipping cell moves along its circle only (the radial move is blocked while
// it slips against its traction): g is the part of s along the circle and z = g/(K_ii + c), the
// inverse of its rotational stiffness -- the circle's curvature adds c = |s|/(mu p) to the cell's
// own compliance K_ii, so a cell that slips far (or has a small disk, at the rim) turns by about
// what Coulomb's law asks, q against s, and no further.
void search_gradient(const Iterate& it, const Mask& stick, const CellScales& scales,
                     FourierPreconditioner& preconditioner, Field& gx, Field& gy, Field& zx,
                     Field& zy, Field& curvature) {
  const Field& bound = *it.problem.bound;
  gx = Field::Zero(bound.rows(), bound.cols());
  gy = gx, zx = gx, zy = gx, curvature = gx;
  Mask free = stick;
  for (Eigen::Index k = 0; k < bound.size(); ++k) {
    if (bound(k) <= 0.0) continue;
    double ax = it.sx(k), ay = it.sy(k);
    if (!stick(k)) {
      const double n = length(it.qx(k), it.qy(k));
      const double hx = it.qx(k) / n, hy = it.qy(k) / n;
      const double along = ax * hx + ay * hy;
      free(k) = along > 0.0;
      if (!free(k)) {
        ax -= along * hx, ay -= along * hy;
        curvature(k) = -along / bound(k);
        const double w = 1.0 / (scales.self_compliance + curvature(k));
        zx(k) = w * ax, zy(k) = w * ay;
      }
    }
    gx(k) = ax, gy(k) = ay;
  }
  Field px = free.select(gx, 0.0), py = free.select(gy, 0.0);
  preconditioner.apply(px);
  preconditioner.apply(py);
  zx = free.select(px / scales.inverse_scale, zx);
  zy = free.select(py / scales.inverse_scale, zy);
}

// The largest in-plane move of the step [m]: the scale of the slip's accuracy.
double move_scale(const Iterate& it) {
  return std::sqrt((it.ux - *it.problem.target_x).square().maxCoeff() +
                   (it.uy - *it.problem.target_y).square().maxCoeff()) +
         std::abs(it.problem.value);
}

}  // namespace

TangentialSolution solve_tangential(RelativeSurfaceResponse& response,
                                    const TangentialProblem& problem, Field qx, Field qy,
                                    const TangentialSettings& settings) {
  COATFFT_REQUIRE(problem.control == TangentialControl::shift,
                  "solve_tangential: a shift, not a load");
  const Field& bound = *problem.bound;
  project_tractions(bound, qx, qy);
  Iterate s{problem, response, std::move(qx), std::move(qy), {}, {}, {}, {}};
  s.displace();
  Mask stick = sticking(bound, s.qx, s.qy);
  TangentialSolution out;
  const auto accept = [&] {
    out.check = check_coulomb(response.grid(), bound, s.qx, s.qy, s.sx, s.sy, std::nullopt,
                              move_scale(s), settings.tolerance);
    return out.check.holds;
  };
  if (!accept()) {
    FourierPreconditioner preconditioner(response.grid());
    const CellScales scales = cell_scales(response, preconditioner, s.applications);
    const Field zero = Field::Zero(bound.rows(), bound.cols());
    Field gx, gy, zx, zy, circle, tx = zero, ty = zero;
    double gz_old = 0.0;
    bool restart = true;
    for (int it = 1; it <= settings.max_iterations; ++it) {
      check_interrupt();
      search_gradient(s, stick, scales, preconditioner, gx, gy, zx, zy, circle);
      const double gz = (gx * zx + gy * zy).sum();
      const double beta = restart || gz_old == 0.0 ? 0.0 : gz / gz_old;
      tx = zx + beta * tx;
      ty = zy + beta * ty;
      gz_old = gz;
      std::array<Field, 3> kt;
      response.apply_in_plane(nullptr, &tx, &ty, kt);
      s.applications += response.applications_per_apply();
      // The step's curvature: the body's, and the circles' for the slipping cells.
      const double curvature =
          (tx * kt[0] + ty * kt[1]).sum() + (circle * (tx.square() + ty.square())).sum();
      const double descent = (gx * tx + gy * ty).sum();
      out.iterations = it;
      if (!(curvature > 0.0) || !(descent > 0.0)) break;  // nothing left to descend
      const double alpha = descent / curvature;
      Field nx = s.qx - alpha * tx, ny = s.qy - alpha * ty;
      project_tractions(bound, nx, ny);
      const double size = (nx.square() + ny.square()).sqrt().sum();
      out.residual =
          size > 0.0 ? ((nx - s.qx).square() + (ny - s.qy).square()).sqrt().sum() / size : 0.0;
      s.qx = std::move(nx);
      s.qy = std::move(ny);
      const Mask next = sticking(bound, s.qx, s.qy);
      restart = (next != stick).any();
      stick = next;
      s.displace();
      if (settings.on_iteration) settings.on_iteration(it, out.residual);
      if (out.residual <= settings.tolerance && accept()) break;
    }
    accept();  // the check of the iterate returned
  }
  out.qx = std::move(s.qx);
  out.qy = std::move(s.qy);
  out.ux = std::move(s.ux);
  out.uy = std::move(s.uy);
  out.sx = std::move(s.sx);
  out.sy = std::move(s.sy);
  out.shift_increment = problem.value;
  out.applications = s.applications;
  return out;
}

namespace {

// The tangential compliance of the contact sticking everywhere [m/N]: u_x averaged over the
// contact under a uniform q_x there, per newton (one application). A sticking contact is the
// stiffest, so it underestimates the shift a load needs.
double stick_compliance(RelativeSurfaceResponse& response, const Field& bound, int& applications) {
  const Grid& g = response.grid();
  const Field unit = (bound > 0.0).select(Field::Ones(bound.rows(), bound.cols()), 0.0);
  std::array<Field, 3> u;
  response.apply_in_plane(nullptr, &unit, nullptr, u);
  applications += response.applications_per_apply();
  const double cells = unit.sum();
  return (unit * u[0]).sum() / cells / (cells * g.dx() * g.dy());
}

}  // namespace

TangentialSolution solve_tangential_load(RelativeSurfaceResponse& response,
                                         const TangentialProblem& problem, Field qx, Field qy,
                                         double guess, const TangentialSettings& settings) {
  const Grid& g = response.grid();
  const double area = g.dx() * g.dy(), target = problem.value;
  const double limit = problem.bound->sum() * area;  // mu P
  TangentialProblem shifted = problem;
  shifted.control = TangentialControl::shift;
  TangentialSolution best;
  int iterations = 0, applications = 0;
  // Q(d) - Q for the shift's increment d, each solve started from the last one's tractions.
  // (Stopping the solves far from the load early, an inexact secant, was measured: as many
  // iterations in all, and more solves.)
  const auto excess = [&](double d) {
    shifted.value = d;
    best = solve_tangential(response, shifted, std::move(qx), std::move(qy), settings);
    iterations += best.iterations;
    applications += best.applications;
    qx = best.qx;
    qy = best.qy;
    return best.qx.sum() * area - target;
  };
  double a = guess, fa = excess(a);
  const double stop = settings.tolerance * limit;
  if (std::abs(fa) > stop) {
    // First the stiffest guess, then outwards until the load is bracketed, then Illinois'
    // regula falsi (Q(d) is monotone and continuous).
    double b = a - fa * stick_compliance(response, *problem.bound, applications), fb = excess(b);
    for (int k = 0; k < 60 && std::abs(fb) > stop && (fa < 0) == (fb < 0); ++k) {
      // Past the secant's root by half again, to bracket it.
      const double grow = fb == fa ? 2.0 : std::clamp(-1.5 * fb / (fb - fa), 0.05, 4.0);
      const double c = b + (b - a) * grow;
      a = b, fa = fb, b = c, fb = excess(b);
    }
    int side = 0;
    for (int k = 0; k < 100 && std::abs(fb) > stop && (fa < 0) != (fb < 0); ++k) {
      const double c = b - fb * (b - a) / (fb - fa);
      const double fc = excess(c);
      if ((fc < 0) == (fb < 0)) {
        fa *= side == -1 ? 0.5 : 1.0;  // Illinois: halve the end that stays
        side = -1;
      } else {
        a = b, fa = fb;
        side = 1;
      }
      b = c, fb = fc;
    }
  }
  best.iterations = iterations;
  best.applications = applications;
  best.check.load_error = std::abs(best.qx.sum() * area - target) / limit;
  best.check.holds = best.check.holds && best.check.load_error <= settings.tolerance;
  return best;
}

}  // namespace coatfft::detail
