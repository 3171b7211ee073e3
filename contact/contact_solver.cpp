#include "contact/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact/fourier_preconditioner.hpp"
#include "core/error.hpp"

namespace coatfft {

namespace {

// Mean of f over the cells where mask is set (mask non-empty).
double masked_mean(const Field& f, const Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>& mask,
                   std::ptrdiff_t count) {
  return mask.select(f, 0.0).sum() / static_cast<double>(count);
}

bool pressure_on_border(const Field& p) {
  const auto nx = p.rows();
  const auto ny = p.cols();
  return (p.row(0) > 0).any() || (p.row(nx - 1) > 0).any() || (p.col(0) > 0).any() ||
         (p.col(ny - 1) > 0).any();
}

void append(std::string& text, const std::string& more) {
  if (!text.empty()) text += "; ";
  text += more;
}

}  // namespace

ContactSolver::ContactSolver(SurfaceOperator& op, ContactOptions options)
    : op_(op), options_(options) {
  COATFFT_REQUIRE(std::isfinite(options_.tolerance) && options_.tolerance > 0,
                  "ContactSolver: tolerance = ", options_.tolerance,
                  ", but it must be finite and > 0");
  COATFFT_REQUIRE(options_.max_iterations >= 1,
                  "ContactSolver: max_iterations = ", options_.max_iterations,
                  ", but it must be >= 1");
  if (options_.preconditioned) {
    preconditioner_ = std::make_unique<detail::FourierPreconditioner>(op_.grid());
  }
}

ContactSolver::~ContactSolver() = default;

ContactResult ContactSolver::solve_load(const Field& height, double load) {
  COATFFT_REQUIRE(std::isfinite(load) && load > 0, "ContactSolver: load = ", load,
                  " N, but the total load must be finite and > 0");
  return run(height, ContactControl::load, load);
}

ContactResult ContactSolver::solve_approach(const Field& height, double approach) {
  COATFFT_REQUIRE(std::isfinite(approach), "ContactSolver: approach = ", approach,
                  " m, but it must be finite");
  return run(height, ContactControl::approach, approach);
}

ContactResult ContactSolver::solve(const Field& height, ContactControl control, double value) {
  return control == ContactControl::load ? solve_load(height, value)
                                         : solve_approach(height, value);
}

ContactResult ContactSolver::run(const Field& h, ContactControl control, double value) {
  using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;
  const Grid& grid = op_.grid();
  const std::ptrdiff_t nx = grid.nx();
  const std::ptrdiff_t ny = grid.ny();
  COATFFT_REQUIRE(h.rows() == nx && h.cols() == ny, "ContactSolver: height field of shape (",
                  h.rows(), ", ", h.cols(), "), but the operator's grid is (", nx, ", ", ny, ")");
  COATFFT_REQUIRE(h.allFinite(), "ContactSolver: the height field has a non-finite entry");
  const bool load_control = control == ContactControl::load;
  const double cell_area = grid.dx() * grid.dy();
  const double h_min = h.minCoeff();
  if (!load_control) {
    COATFFT_REQUIRE(value > h_min, "ContactSolver: approach = ", value,
                    " m, but it must exceed min(height) = ", h_min,
                    " m, or the indenter does not touch the surface");
  }
  const double delta = load_control ? 0.0 : value;  // approach control: the fixed approach

  ContactResult result;
  result.control = control;
  Field p(nx, ny);
  Field u(nx, ny);
  Field g(nx, ny);
  Field t = Field::Zero(nx, ny);
  Field r(nx, ny);
  Field p_old(nx, ny);
  Field z(nx, ny);  // preconditioned gap (aliases g's role when not preconditioned)

  if (load_control) {
    // Polonsky & Keer's start: the load spread uniformly over the whole domain.
    p.setConstant(value / (static_cast<double>(nx * ny) * cell_area));
  } else {
    // A uniform pressure on the geometric overlap {h < delta}, scaled so that the mean gap over
    // it vanishes: one extra application, and a start of the right magnitude.
    const Mask overlap = h < delta;
    const auto n_overlap = overlap.count();
    p = overlap.cast<double>();
    op_.apply(p, u);
    const double scale =
        masked_mean(delta - h, overlap, n_overlap) / masked_mean(u, overlap, n_overlap);
    COATFFT_REQUIRE(std::isfinite(scale) && scale > 0, "ContactSolver: operator '", op_.name(),
                    "' returned a non-positive mean displacement under a positive pressure");
    p *= scale;
  }

  // The iteration below is written as a few fused loops over the cells (no temporaries): at large
  // N the element-wise work would otherwise rival the two FFT-based applications per iteration.
  const std::ptrdiff_t n_cells = nx * ny;
  const double* hd = h.data();
  double* pd = p.data();
  double* gd = g.data();
  double* td = t.data();
  double* qd = p_old.data();
  double* zd = z.data();
  double g_dot_z_old = 1.0;
  bool conjugate = false;  // Polonsky & Keer's delta: keep the previous direction (no new contacts)
  double residual = std::numeric_limits<double>::infinity();
  int iteration = 0;
  while (iteration < options_.max_iterations) {
    ++iteration;
    // Step 1: gap of the current pressure; on the contact set I_c = {p > 0} it should be constant
    // (load control: its mean is the unknown approach) or zero (approach control).
    op_.apply(p, u);
    const double* ud = u.data();  // fetched after apply: an operator may reallocate its output
    std::ptrdiff_t n_contact = 0;
    double g_sum = 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      gd[k] = hd[k] + ud[k] - delta;
      if (pd[k] > 0) {
        ++n_contact;
        g_sum += gd[k];
      }
    }
    if (n_contact == 0) {
      append(result.warning, "all pressure vanished (breakdown)");
      break;
    }
    const double g_mean = load_control ? g_sum / static_cast<double>(n_contact) : 0.0;
    double g_norm = 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      gd[k] -= g_mean;
      if (pd[k] > 0) g_norm += gd[k] * gd[k];
    }
    if (g_norm == 0.0) {  // exact solution on I_c already
      residual = 0.0;
      result.converged = true;
      break;
    }
    // Step 2: search direction. Preconditioned: z = P M P g with M ~ K^-1 (the |k| multiplier) and
    // P the restriction to I_c (and, under load control, to zero mean on I_c, the tangent space of
    // the load constraint); P M P is symmetric positive definite there, so this is preconditioned
    // CG on the contact block, and a constant in g still cancels. Unpreconditioned: z = g.
    double g_dot_z = g_norm;
    const double* direction = gd;
    if (preconditioner_) {
      for (std::ptrdiff_t k = 0; k < n_cells; ++k) zd[k] = pd[k] > 0 ? gd[k] : 0.0;
      preconditioner_->apply(z);
      double z_mean = 0.0;
      if (load_control) {
        for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
          if (pd[k] > 0) z_mean += zd[k];
        }
        z_mean /= static_cast<double>(n_contact);
      }
      g_dot_z = 0.0;
      for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
        zd[k] = pd[k] > 0 ? zd[k] - z_mean : 0.0;
        g_dot_z += gd[k] * zd[k];
      }
      direction = zd;
    }
    // Conjugate direction on I_c (PK eqs. for t); restart when the set grew.
    const double beta = conjugate ? g_dot_z / g_dot_z_old : 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      td[k] = pd[k] > 0 ? direction[k] + beta * td[k] : 0.0;
    }
    g_dot_z_old = g_dot_z;
    // Step 3: step length along t. Under load control the mean of K t over I_c is removed: a
    // constant displacement is absorbed by the approach, so it must not steer the step. This is
    // also what makes the iterates independent of the operator's g(0).
    op_.apply(t, r);
    const double* rd = r.data();
    double r_mean = 0.0;
    if (load_control) {
      for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
        if (pd[k] > 0) r_mean += rd[k];
      }
      r_mean /= static_cast<double>(n_contact);
    }
    double numerator = 0.0;
    double denominator = 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      if (pd[k] > 0) {
        numerator += gd[k] * td[k];
        denominator += (rd[k] - r_mean) * td[k];
      }
    }
    if (!(denominator > 0) || !std::isfinite(numerator)) {
      append(result.warning, "non-positive curvature along the search direction (breakdown)");
      break;
    }
    const double tau = numerator / denominator;
    // Step 4: update, project on p >= 0, and put pressure on cells that overlap (p = 0, g < 0).
    conjugate = true;
    double p_sum = 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      qd[k] = pd[k];
      double pk = std::max(pd[k] - tau * td[k], 0.0);
      if (pk == 0.0 && gd[k] < 0.0) {
        pk = -tau * gd[k];
        conjugate = false;
      }
      pd[k] = pk;
      p_sum += pk;
    }
    if (!(p_sum > 0) || !std::isfinite(p_sum)) {
      append(result.warning, "all pressure vanished (breakdown)");
      p = p_old;
      break;
    }
    // Step 5 (load control): enforce the total load exactly; then the relative change.
    const double scale = load_control ? value / (p_sum * cell_area) : 1.0;
    double change = 0.0;
    for (std::ptrdiff_t k = 0; k < n_cells; ++k) {
      pd[k] *= scale;
      change += std::abs(pd[k] - qd[k]);
    }
    residual = change / (scale * p_sum);
    if (residual < options_.tolerance) {
      result.converged = true;
      break;
    }
  }

  op_.apply(p, u);
  const Mask contact = p > 0;
  const auto n_contact = contact.count();
  double approach = delta;
  if (load_control) approach = n_contact > 0 ? masked_mean(h + u, contact, n_contact) : h_min;
  result.gap = h + u - approach;
  result.pressure = std::move(p);
  result.displacement = std::move(u);
  result.load = result.pressure.sum() * cell_area;
  if (!load_control || options_.compute_approach) result.approach = approach;
  result.contact_area = static_cast<double>(n_contact) * cell_area;
  if (n_contact > 0) result.contact_radius = std::sqrt(result.contact_area / std::numbers::pi);
  result.max_pressure = result.pressure.maxCoeff();
  result.iterations = iteration;
  result.residual = residual;
  result.touches_boundary = pressure_on_border(result.pressure);
  if (result.touches_boundary) {
    append(result.warning,
           "contact reaches the domain edge (pressure > 0 on a border cell): the domain is too "
           "small for this load");
  }
  if (!result.converged && result.warning.find("breakdown") == std::string::npos) {
    append(result.warning,
           detail::concat("not converged after ", iteration, " iterations (residual ", residual,
                          ", tolerance ", options_.tolerance, ")"));
  }
  return result;
}

}  // namespace coatfft
