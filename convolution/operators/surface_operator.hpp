#pragma once
// The one interface every displacement operator implements: surface normal displacement from a
// piecewise-constant surface pressure on a Grid. Contact solvers, the CLI and the benchmarks see
// only this. An operator is a plan: everything that depends on sizes is built in the constructor;
// apply() only computes. Not safe to call apply() on one instance from two threads at once.
#include <memory>
#include <string>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../method.hpp"

namespace coatfft {

class SurfaceOperator {
 public:
  virtual ~SurfaceOperator() = default;
  SurfaceOperator() = default;
  SurfaceOperator(const SurfaceOperator&) = delete;
  SurfaceOperator& operator=(const SurfaceOperator&) = delete;

  /// The grid of the pressure and displacement fields.
  virtual const Grid& grid() const = 0;
  /// u = displacement [m, positive into the body] from p = pressure [Pa, positive compressive],
  /// both Fields of shape (nx, ny) (a distributed operator's: this rank's rows, (nx, rows)). `u`
  /// is resized if needed; it must not alias `p`.
  virtual void apply(const Field& pressure, Field& displacement) = 0;
  /// The method this operator runs (DC-FFT on a split kernel reports frf-split, not dcfft).
  virtual Method method() const = 0;
  /// Its name as used in scene files and summary.json ("dcfft", "frf-split", ...).
  std::string name() const { return std::string(to_string(method())); }
  /// Whether the surface repeats over the grid's period (no domain edge); false for the free
  /// surfaces of a half-space.
  virtual bool periodic() const { return false; }
  /// The same body on the grid with half the cells per side (same lx, ly; nx and ny even), as the
  /// Galerkin coarse operator (convolution/kernels/detail/coarse_kernel.hpp), for the contact
  /// solver's coarse-to-fine start; costs about one application. Null where the grid has an odd
  /// side or the operator kind offers none (only the periodic and DC-FFT operators do).
  virtual std::unique_ptr<SurfaceOperator> coarsened() { return nullptr; }

  /// Allocating convenience form (the displacement of the pressure's shape).
  Field apply(const Field& pressure);

  /// The displacement of a unit pressure [1 Pa] on cell (0, 0) (one application): the kernel's
  /// coefficients K(i, j) at the offsets i, j >= 0 (modulo the period on a periodic grid). A
  /// distributed operator returns this rank's rows of it.
  virtual Field unit_response();
};

}  // namespace coatfft
