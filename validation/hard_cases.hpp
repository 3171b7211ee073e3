#pragma once
// The hard bodies of issue 6 ("numerical stability on hard cases": thin stiff coating, thick soft
// coating, nu = 0.4999 in either medium) and the FRF methods run on them, shared by
// validation/hard_cases_table.cpp (docs/validation_hard_cases.md) and tests/test_hard_cases.cpp:
// a cell-averaged Hertz pressure through frf-spectral, frf-dcfft (regularized g(0)) or frf-split,
// compared with the continuous Hankel displacement (validation/hankel_displacement.hpp) at the
// cell centres nearest a few radii. Units: contact radius a, substrate modulus E2 = 1 Pa.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "convolution/dcfft_operator.hpp"
#include "convolution/frf_dcfft_operator.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "convolution/g0.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "convolution/surface_operator.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/types.hpp"
#include "frf/coated_frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"
#include "validation/hankel_displacement.hpp"

namespace coatfft::hard_cases {

struct HardBody {
  std::string label;
  CoatedFrf frf;
};

/// The five bodies, lengths in units of `a` [m], substrate E2 = 1 Pa: thin stiff (h/a = 1e-3,
/// E1/E2 = 100), thick soft (h/a = 50, E1/E2 = 0.01), coating nu = 0.4999 bonded and frictionless
/// and substrate nu = 0.4999 (h/a = 0.1, E1/E2 = 0.1; the other medium nu = 0.3).
inline std::vector<HardBody> bodies(double a) {
  const Interface b = Interface::bonded;
  return {{"thin stiff: h/a = 1e-3, E1/E2 = 100, bonded",
           CoatedFrf(Material(100.0, 0.3), 1e-3 * a, Material(1.0, 0.3), b)},
          {"thick soft: h/a = 50, E1/E2 = 0.01, bonded",
           CoatedFrf(Material(0.01, 0.3), 50.0 * a, Material(1.0, 0.3), b)},
          {"coating nu 0.4999: h/a = 0.1, E1/E2 = 0.1, bonded",
           CoatedFrf(Material(0.1, 0.4999), 0.1 * a, Material(1.0, 0.3), b)},
          {"coating nu 0.4999: h/a = 0.1, E1/E2 = 0.1, frictionless",
           CoatedFrf(Material(0.1, 0.4999), 0.1 * a, Material(1.0, 0.3), Interface::frictionless)},
          {"substrate nu 0.4999: h/a = 0.1, E1/E2 = 0.1, bonded",
           CoatedFrf(Material(0.1, 0.3), 0.1 * a, Material(1.0, 0.4999), b)}};
}

/// An FRF method: "frf-spectral" or "frf-dcfft" with extension ratio alpha, or "frf-split"
/// (alpha unused, 0).
struct Method {
  std::string name;
  double alpha = 0.0;
};

inline std::string method_label(const Method& m) {
  return m.name == "frf-split" ? m.name : m.name + " a" + std::to_string(std::lround(m.alpha));
}

/// The operator of `m` on `grid` and `frf`, g(0) regularized; `threads` for FFTW, FRF sampling
/// and the split kernel's loops.
inline std::unique_ptr<SurfaceOperator> make_operator(const Grid& grid, const Frf& frf,
                                                      const Method& m, int threads = 1) {
  if (m.name == "frf-spectral")
    return std::make_unique<FrfSpectralOperator>(grid, frf, m.alpha, G0Method::regularized,
                                                 default_g0_tolerance, Planning::estimate, threads);
  if (m.name == "frf-dcfft")
    return frf_dcfft_operator(grid, frf, m.alpha, G0Method::regularized, default_g0_tolerance,
                              nullptr, Planning::estimate, threads);
  COATFFT_REQUIRE(m.name == "frf-split", "hard_cases: unknown method '", m.name, "'");
  SplitKernelOptions options;
  options.threads = threads;
  return std::make_unique<DcfftOperator>(split_frf_kernel_quarter(grid, frf, options),
                                         Planning::estimate, threads);
}

/// A cell of the grid and the distance of its centre from the origin [m].
struct Probe {
  std::ptrdiff_t i = 0;
  std::ptrdiff_t j = 0;
  double r = 0.0;
};

/// The cell whose centre is nearest (x, y) [m].
inline Probe nearest_cell(const Grid& g, double x, double y) {
  const auto index = [](double s, double l, double d, std::ptrdiff_t n) {
    const auto k = static_cast<std::ptrdiff_t>(std::lround((s + 0.5 * l) / d - 0.5));
    return std::clamp<std::ptrdiff_t>(k, 0, n - 1);
  };
  Probe p{index(x, g.lx(), g.dx(), g.nx()), index(y, g.ly(), g.dy(), g.ny()), 0.0};
  p.r = std::hypot(g.x(p.i), g.y(p.j));
  return p;
}

/// Cell-averaged Hertz pressure (p0 = 1 Pa, radius a [m]) on `grid` over `frf`, with the Hankel
/// reference at the cell centres nearest (r, 0) for r/a in `radii_over_a` and at r = 0 exactly.
struct HertzProblem {
  Field pressure;
  std::vector<Probe> probes;
  std::vector<double> reference;  ///< u_ref at the probes' radii [m]
  double u0 = 0.0;                ///< u_ref(0) [m]
};

inline HertzProblem hertz_problem(const Grid& grid, const Frf& frf, double a,
                                  const std::vector<double>& radii_over_a, double rel_tol = 1e-10) {
  HertzProblem pb{hertz_pressure(grid, 1.0, a, Sampling::cell_average), {}, {}, 0.0};
  pb.u0 = hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, a, 0.0, rel_tol);
  for (double r : radii_over_a) {
    pb.probes.push_back(nearest_cell(grid, r * a, 0.0));
    pb.reference.push_back(
        hankel_displacement(frf, AxisymmetricLoad::hertz, 1.0, a, pb.probes.back().r, rel_tol));
  }
  return pb;
}

/// One method on one problem.
struct MethodResult {
  bool finite = true;          ///< every value of u is finite
  std::vector<double> errors;  ///< (u - u_ref) / u_ref(0) at the probes [-]
  double setup_seconds = 0.0;  ///< wall time of the operator's construction [s]
  double max_abs_error() const {
    double w = 0.0;
    for (double e : errors) w = std::max(w, std::abs(e));
    return std::isfinite(w) ? w : HUGE_VAL;
  }
};

inline MethodResult run_method(const Grid& grid, const Frf& frf, const HertzProblem& pb,
                               const Method& m, int threads = 1) {
  MethodResult res;
  const auto t0 = std::chrono::steady_clock::now();
  const std::unique_ptr<SurfaceOperator> op = make_operator(grid, frf, m, threads);
  res.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Field u = op->apply(pb.pressure);
  res.finite = u.allFinite();
  for (std::size_t k = 0; k < pb.probes.size(); ++k)
    res.errors.push_back((u(pb.probes[k].i, pb.probes[k].j) - pb.reference[k]) / pb.u0);
  return res;
}

}  // namespace coatfft::hard_cases
