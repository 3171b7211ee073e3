#include "convolution/operators/pipeline_error.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "convolution/kernels/frf_influence_kernel.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/frf_spectral_operator.hpp"
#include "core/error.hpp"
#include "frf/half_space_frf.hpp"
#include "materials/material.hpp"

namespace coatfft {
namespace {

constexpr const char* estimate_name = "predicted_pipeline_error";

// Cells across the shorter side of the proxy: the homogeneous error is converged in N there to
// ~1 % at alpha = 2 and 4 and ~4 % at alpha = 8 (docs/validation/pipeline_error.md, section 2).
constexpr double proxy_cells = 64.0;
// Points of the extended lattice max(alpha, 2)^2 px py of a proxy (8 MiB per real array): 64^2
// cells up to alpha = 11, beyond which the proxy is coarsened rather than made expensive.
constexpr double lattice_budget = 524288.0;
// The FRF model's reference is the split kernel, whose cost grows quickly with elongated cells and
// with the number of cells (docs/split_kernel.md): its proxy has square cells, at most 64^2 of
// them, at least 8 across, or the homogeneous model is used.
constexpr double coated_max_cells = 4096.0;
constexpr double coated_max_aspect = 4.0;
constexpr std::ptrdiff_t coated_min_cells = 8;

double min_alpha(Method method) {
  return method == Method::frf_dcfft ? 2.0 : 1.0;
}

void check_arguments(const Grid& grid, Method method, double alpha) {
  COATFFT_REQUIRE(samples_frf_lattice(method), estimate_name, ": method \"", to_string(method),
                  "\" has no periodisation error; the model applies to \"frf-spectral\" and "
                  "\"frf-dcfft\" only");
  extended_size(grid.nx(), alpha, min_alpha(method), estimate_name);
  extended_size(grid.ny(), alpha, min_alpha(method), estimate_name);
}

// The smallest q in 1..64 for which alpha q is a whole number (to extended_size's 1e-9), 0 if none.
std::ptrdiff_t alpha_denominator(double alpha) {
  for (std::ptrdiff_t q = 1; q <= 64; ++q) {
    const double m = alpha * static_cast<double>(q);
    if (std::abs(m - std::round(m)) <= 1e-9 * m) return q;
  }
  return 0;
}

std::ptrdiff_t round_up(std::ptrdiff_t t, std::ptrdiff_t q) {
  return (t + q - 1) / q * q;
}

// The largest 7-smooth number (2^a 3^b 5^c 7^d) <= t, t >= 1: proxy sizes FFTW transforms fast
// (a prime size near 4000 costs several times a smooth one).
std::ptrdiff_t smooth_at_most(std::ptrdiff_t t) {
  for (;; --t) {
    std::ptrdiff_t m = t;
    for (const std::ptrdiff_t f : {2, 3, 5, 7})
      while (m % f == 0) m /= f;
    if (m == 1) return t;
  }
}

double cell_aspect(const Grid& g) {
  const double r = g.dx() / g.dy();
  return std::max(r, 1.0 / r);
}

// A proxy size near t for a grid axis of n cells, a multiple of `step`: n itself when t reaches
// it, otherwise a 7-smooth size (FFTW transforms a prime size near 4000 several times slower) of
// n's parity where `step` allows, so that the load sits on a cell boundary (n even) or a cell
// centre (n odd) as on the grid: for a load narrower than a cell that decides max |u|.
std::ptrdiff_t proxy_size(std::ptrdiff_t t, std::ptrdiff_t n, std::ptrdiff_t step) {
  const bool divides = n % step == 0;
  if (t >= n && divides) return n;
  std::ptrdiff_t p = round_up(smooth_at_most(std::min(t, n)), step);
  if ((p - n) % 2 != 0 && step % 2 != 0) p += step;
  return divides ? std::min(p, n) : p;
}

// A proxy of about tx x ty cells on grid's domain on which alpha px and alpha py are whole
// numbers. alpha's own denominator q divides nx and ny (make_operator's condition), so sizes that
// are multiples of q keep alpha exactly; when q > 64, or when they would more than double the
// cells, alpha drops to a multiple of 1/8 (then of 1) below it, which can only raise the
// predicted error (it falls with alpha).
PipelineErrorProxy fitted_proxy(const Grid& grid, std::ptrdiff_t tx, std::ptrdiff_t ty,
                                double alpha, double max_cells) {
  const std::ptrdiff_t q = alpha_denominator(alpha);
  if (q > 0) {
    const std::ptrdiff_t px = proxy_size(tx, grid.nx(), q), py = proxy_size(ty, grid.ny(), q);
    if (static_cast<double>(px * py) <= 2.0 * max_cells)
      return {Grid(px, py, grid.lx(), grid.ly()), alpha};
  }
  for (const std::ptrdiff_t step : {8, 1}) {
    const double s = static_cast<double>(step);
    const double reduced = std::floor(alpha * s * (1.0 + 1e-12)) / s;
    const std::ptrdiff_t px = proxy_size(tx, grid.nx(), step);
    const std::ptrdiff_t py = proxy_size(ty, grid.ny(), step);
    if (static_cast<double>(px * py) <= 2.0 * max_cells || step == 1)
      return {Grid(px, py, grid.lx(), grid.ly()), reduced};
  }
  return {grid, alpha};  // not reached: step 1 always returns
}

// The cells of the FRF model's proxy; nullopt when square cells would be too many or too few.
std::optional<PipelineErrorProxy> coated_proxy(const Grid& grid, const PipelineErrorProxy& proxy) {
  // A small proxy with nearly square cells is used as it is: the prediction is then the error
  // measured with the body's FRF, not a transfer of it.
  if (static_cast<double>(proxy.grid.nb_cells()) <= coated_max_cells &&
      cell_aspect(proxy.grid) <= coated_max_aspect)
    return proxy;
  const double a2 = std::max(proxy.alpha, 2.0);
  const double max_cells = std::min(coated_max_cells, lattice_budget / (a2 * a2));
  const double lx = grid.lx(), ly = grid.ly();
  const double d = std::max(std::min(lx, ly) / proxy_cells, std::sqrt(lx / max_cells * ly));
  const auto cells = [d](double length, std::ptrdiff_t n) {
    return static_cast<std::ptrdiff_t>(std::min(static_cast<double>(n), std::round(length / d)));
  };
  const std::ptrdiff_t tx = std::max<std::ptrdiff_t>(1, cells(lx, grid.nx()));
  const std::ptrdiff_t ty = std::max<std::ptrdiff_t>(1, cells(ly, grid.ny()));
  if (std::min(tx, ty) < coated_min_cells) return std::nullopt;
  const PipelineErrorProxy c = fitted_proxy(grid, tx, ty, proxy.alpha, max_cells);
  if (cell_aspect(c.grid) > coated_max_aspect) return std::nullopt;
  return c;
}

// The pipeline `method` for `frf` on `grid` as make_operator builds it with its default options
// (regularized g(0), FFTW_ESTIMATE); without the factory, which would predict its error in turn.
std::unique_ptr<SurfaceOperator> pipeline_operator(const Grid& grid, const Frf& frf, Method method,
                                                   double alpha, int threads) {
  const G0Result g0 = lattice_g0(grid, frf, alpha, min_alpha(method), G0Method::regularized,
                                 default_g0_tolerance, estimate_name);
  if (method == Method::frf_spectral)
    return std::make_unique<FrfSpectralOperator>(grid, frf, alpha, g0, Planning::estimate, threads);
  return std::make_unique<DcfftOperator>(frf_dcfft_kernel(grid, frf, alpha, g0, threads),
                                         Planning::estimate, threads);
}

// max |u_pipeline - u_exact| / max |u_exact| under the reference load on the proxy.
double error_against(const PipelineErrorProxy& proxy, const Frf& frf, Method method,
                     SurfaceOperator& exact, int threads) {
  const Field p = pipeline_error_reference_load(proxy.grid);
  const Field reference = exact.apply(p);
  const Field u = pipeline_operator(proxy.grid, frf, method, proxy.alpha, threads)->apply(p);
  return (u - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

double homogeneous_error(const PipelineErrorProxy& proxy, Method method, int threads) {
  // E* = 1: the relative error of a half-space does not depend on its modulus.
  const HalfSpaceFrf unit(Material(1.0, 0.0));
  DcfftOperator love(love_kernel(proxy.grid, 1.0, threads), Planning::estimate, threads);
  return error_against(proxy, unit, method, love, threads);
}

double coated_error(const PipelineErrorProxy& proxy, const Frf& frf, Method method, int threads) {
  // A reference to ~1e-6 of u is plenty for an error of 1e-3 or more; the alias fold capped at
  // order 4 (coatings much thinner than a proxy cell) changes u by ~1e-7 and saves up to 97 % of
  // the kernel's time (measured on TiN 2 um over 3 mm at 64^2: 9 ms instead of 300 ms).
  SplitKernelOptions options;
  options.tolerance = 1e-6;
  options.max_alias_order = 4;
  options.threads = threads;
  DcfftOperator split(split_frf_kernel(proxy.grid, frf, options), Planning::estimate, threads);
  return error_against(proxy, frf, method, split, threads);
}

// True when `frf` is within 1 % of the substrate's C0/k from the proxy's longest period to 8/a
// (a the reference load's radius), where the load's spectrum has fallen to a few percent: the
// coating is then too thin (or the body too nearly homogeneous) to change the error, which the
// homogeneous model gives at a fraction of the split kernel's cost. TiN 2 um under a 1 mm load
// passes (FRF model within 0.5 % of the homogeneous one, docs/validation/pipeline_error.md); a
// half-space passes exactly.
bool homogeneous_enough(const Frf& frf, const PipelineErrorProxy& proxy) {
  const double c0 = frf.c0();
  const Grid& g = proxy.grid;
  const double k_low = 2.0 * std::numbers::pi / (proxy.alpha * std::max(g.lx(), g.ly()));
  const double k_high = std::max(k_low, 24.0 / std::min(g.lx(), g.ly()));  // 8/a, a = L/3
  // All samples in one batch (Frf::evaluate): for an FRF with a cost per call that beats
  // stopping at the first one outside.
  constexpr int samples = 32;
  std::vector<double> k(samples);
  for (int i = 0; i < samples; ++i)
    k[static_cast<std::size_t>(i)] = k_low * std::pow(k_high / k_low, i / (samples - 1.0));
  std::vector<double> h(k.size());
  frf.evaluate(k, h);
  for (std::size_t i = 0; i < k.size(); ++i)
    if (!(std::abs(k[i] * h[i] / c0 - 1.0) <= 1e-2)) return false;
  return true;
}

// The split kernel needs a finite positive c0 and c_inf (docs/split_kernel.md).
bool splittable(const Frf& frf) {
  const double c0 = frf.c0(), c_inf = frf.c_inf();
  return std::isfinite(c0) && c0 > 0 && std::isfinite(c_inf) && c_inf > 0;
}

// Midpoint nodes and weights of the part of cell [centre - d/2, centre + d/2] inside [-a, a]:
// sub-intervals of at most a/8, weights summing to the fraction of the cell covered.
void cell_nodes(double centre, double d, double a, std::vector<double>& x, std::vector<double>& w) {
  x.clear();
  w.clear();
  const double lo = std::max(centre - 0.5 * d, -a), hi = std::min(centre + 0.5 * d, a);
  if (!(hi > lo)) return;
  const double parts = std::clamp(std::ceil(8.0 * (hi - lo) / a), 1.0, 16.0);
  const double h = (hi - lo) / parts;
  for (int k = 0; k < static_cast<int>(parts); ++k) {
    x.push_back(lo + (k + 0.5) * h);
    w.push_back(h / d);
  }
}

}  // namespace

PipelineErrorProxy pipeline_error_proxy(const Grid& grid, double alpha) {
  COATFFT_REQUIRE(std::isfinite(alpha) && alpha >= 1, "pipeline_error_proxy: alpha = ", alpha,
                  " must be finite and >= 1");
  const double shorter = std::min(grid.lx(), grid.ly());
  // Cells no smaller than shorter/64 along each axis, never more than the grid has; the factor
  // 1 - 1e-12 keeps ceil(64 * 1) at 64 when length/shorter rounds above 1.
  const auto target = [&](std::ptrdiff_t n, double length) {
    return std::min(static_cast<double>(n),
                    std::ceil(proxy_cells * (length / shorter) * (1 - 1e-12)));
  };
  double tx = target(grid.nx(), grid.lx()), ty = target(grid.ny(), grid.ly());
  const double a2 = std::max(alpha, 2.0);
  const double max_cells = lattice_budget / (a2 * a2);
  if (tx * ty > max_cells) {
    // Both axes coarsened alike (the cells keep their shape); an axis that reaches one cell leaves
    // the rest of the budget to the other.
    const double s = std::sqrt(max_cells / (tx * ty));
    tx = std::max(1.0, std::floor(tx * s));
    ty = std::max(1.0, std::floor(ty * s));
    if (tx * ty > max_cells) (tx == 1.0 ? ty : tx) = std::floor(max_cells / (tx == 1.0 ? 1.0 : ty));
  }
  return fitted_proxy(grid, static_cast<std::ptrdiff_t>(tx), static_cast<std::ptrdiff_t>(ty), alpha,
                      max_cells);
}

Field pipeline_error_reference_load(const Grid& grid) {
  const double a = std::min(grid.lx(), grid.ly()) / 3.0;
  Field p = Field::Zero(grid.nx(), grid.ny());
  std::vector<double> xs, wx, ys, wy;
  // Only the cells that meet the load's bounding square [-a, a]^2 carry load.
  const auto first = [a](double length, double d) {
    return static_cast<std::ptrdiff_t>(std::max(0.0, std::floor((0.5 * length - a) / d) - 1.0));
  };
  const std::ptrdiff_t i0 = first(grid.lx(), grid.dx()), j0 = first(grid.ly(), grid.dy());
  for (std::ptrdiff_t j = j0; j < grid.ny() - j0; ++j) {
    cell_nodes(grid.y(j), grid.dy(), a, ys, wy);
    if (ys.empty()) continue;
    for (std::ptrdiff_t i = i0; i < grid.nx() - i0; ++i) {
      cell_nodes(grid.x(i), grid.dx(), a, xs, wx);
      double sum = 0.0;
      for (std::size_t v = 0; v < ys.size(); ++v)
        for (std::size_t u = 0; u < xs.size(); ++u) {
          const double s = 1.0 - (xs[u] * xs[u] + ys[v] * ys[v]) / (a * a);
          if (s > 0) sum += wx[u] * wy[v] * std::sqrt(s);
        }
      p(i, j) = sum;
    }
  }
  return p;
}

double predicted_pipeline_error(const Grid& grid, Method method, double alpha, int threads) {
  check_arguments(grid, method, alpha);
  COATFFT_REQUIRE(threads >= 1, estimate_name, ": threads = ", threads, ", but must be >= 1");
  return homogeneous_error(pipeline_error_proxy(grid, alpha), method, threads);
}

double predicted_pipeline_error(const Grid& grid, const Frf& frf, Method method, double alpha,
                                int threads) {
  check_arguments(grid, method, alpha);
  COATFFT_REQUIRE(threads >= 1, estimate_name, ": threads = ", threads, ", but must be >= 1");
  const PipelineErrorProxy proxy = pipeline_error_proxy(grid, alpha);
  if (!splittable(frf) || homogeneous_enough(frf, proxy))
    return homogeneous_error(proxy, method, threads);
  const std::optional<PipelineErrorProxy> coated = coated_proxy(grid, proxy);
  if (!coated) return homogeneous_error(proxy, method, threads);
  double e = 0.0;
  try {
    e = coated_error(*coated, frf, method, threads);
  } catch (const InvalidArgument&) {
    // The FRF model's reference (the split kernel) refuses this FRF: the homogeneous model
    // answers instead, since a prediction must not fail a build the pipeline itself accepts.
    return homogeneous_error(proxy, method, threads);
  }
  if (coated->grid == proxy.grid && coated->alpha == proxy.alpha) return e;
  // The coating's factor, measured on the square-celled proxy, carried over to the homogeneous
  // prediction of the finer (or more elongated) one: docs/theory.md 4.6.3.
  return homogeneous_error(proxy, method, threads) * e /
         homogeneous_error(*coated, method, threads);
}

}  // namespace coatfft
