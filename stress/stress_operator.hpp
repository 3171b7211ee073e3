#pragma once
// Stresses on planes z = const inside a layered body under surface loads: the linear convolution
// of the cell-integrated loads with each plane's influence coefficients (stress/stress_kernel.hpp),
// computed exactly (to rounding) as a circular one on a zero-padded grid, as DC-FFT does for the
// surface displacement (Liu, Wang & Liu 2000). On a periodic surface, the circular convolution
// over the period with the planes' spectra on its own lattice (no padding), exact for loads
// repeated over the periods. Everything is planned in the constructor; apply()
// transforms each load once, then per plane multiplies and runs six inverse transforms: a plane
// costs about three surface applications (docs/stress.md).
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "../convolution/fft/parity_convolution.hpp"
#include "../convolution/fft/planning.hpp"
#include "../convolution/method.hpp"
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "../frf/stress_frf.hpp"
#include "../layers/layer_stack.hpp"
#include "stress_kernel.hpp"

namespace coatfft {

/// Six stress fields per plane, in stress.npy's order (xx, yy, zz, yz, xz, xy), each (nx, ny) [Pa].
using PlaneStress = std::array<Field, 6>;

struct StressOperatorOptions {
  StressKernelOptions kernel;  ///< how each plane's coefficients are made
  /// Medium of a depth on an interface (within LayerStack::locate's tolerance of its depth).
  InterfaceSide side = InterfaceSide::below;
  /// The medium of each depth in turn, where planes differ (an interface seen from both sides):
  /// empty, or one per depth, replacing `side`.
  std::vector<InterfaceSide> sides = {};
  /// Whether the tractions q_x, q_y are loads too (their kernels cost twice the pressure's).
  bool tangential = false;
  /// Boundary::periodic: the surface repeats over the grid's domain (nx, ny even):
  /// periodic_stress_spectra's kernels, kernel.alpha unused.
  Boundary boundary = Boundary::free;
  Planning planning = Planning::estimate;
  /// Called, when set, before the kernels of the planes first .. first + count - 1 (0-based, in
  /// the order of the depths) are made, with the number of planes: their set-up is most of an
  /// operator's cost, so a caller can show how far it is. It runs on the constructing thread.
  std::function<void(std::size_t first, std::size_t count, std::size_t planes)> on_planes;
};

/// Throws InvalidArgument unless `depths` [m] is a plane list StressOperator computes: 1 to
/// StressOperator::max_planes depths, each finite and > 0 (the front ends check it first, before
/// they estimate the memory of the planes).
void require_stress_depths(const std::vector<double>& depths);

/// An upper estimate of the bytes a StressOperator of `planes` planes on `grid` takes while
/// built and applied (its spectra, a group's kernel construction, the output fields), for a
/// memory check before any allocation (core/memory.hpp); `alpha` as StressKernelOptions::alpha.
double estimated_stress_bytes(const Grid& grid, std::size_t planes, int alpha, bool tangential,
                              Boundary boundary = Boundary::free);

class StressOperator {
 public:
  /// The most planes one operator computes: each holds six spectra of the padded lattice, and a
  /// request beyond this is a typing error rather than a computation (every front end's limit).
  static constexpr std::size_t max_planes = 512;

  /// Plans the planes at `depths` [m] (each finite, > 0) of the body `stack` on `grid`.
  /// Throws InvalidArgument on bad options, an empty or non-finite depth list, more than
  /// max_planes depths, or tangential
  /// loads on a stack with a frictionless interface (a net tangential force has no equilibrium
  /// there: the coating slides, docs/theory.md 2.3), or planes so shallow that their kernels
  /// exceed options.kernel.max_evaluations (stress_kernel_evaluations).
  StressOperator(const Grid& grid, const LayerStack& stack, std::vector<double> depths,
                 const StressOperatorOptions& options = {});

  const Grid& grid() const { return convolution_.grid(); }
  const std::vector<double>& depths() const { return depths_; }
  bool tangential() const { return tangential_; }
  bool periodic() const { return convolution_.periodic(); }

  /// The stresses on every plane under the pressure (compression positive) and, for a
  /// tangential operator, the tractions q_x, q_y the surface receives (null: zero), each
  /// (nx, ny) [Pa] as cell values. `stress` is resized to one PlaneStress per depth.
  void apply(const Field& pressure, const Field* qx, const Field* qy,
             std::vector<PlaneStress>& stress);

  /// Wall-clock seconds of the constructor [s], and the kernels' reports, one per plane.
  double setup_seconds() const { return setup_seconds_; }
  const std::vector<StressKernelReport>& kernel_reports() const { return reports_; }
  /// Bytes the operator holds (kernel spectra and buffers).
  std::size_t memory_bytes() const { return convolution_.memory_bytes(); }

 private:
  std::vector<double> depths_;
  bool tangential_;
  ParityConvolution convolution_;  // outputs 6 p + c: plane p, component c
  std::vector<Field> fields_;      // apply()'s outputs before they are moved into planes
  std::vector<StressKernelReport> reports_;
  double setup_seconds_ = 0.0;

  void add_planes(const Grid& grid, const LayerStack& stack, std::size_t first, std::size_t count,
                  InterfaceSide side, const StressOperatorOptions& options);
};

/// The factory of the stress operator, the counterpart of make_operator and
/// make_tangential_operator (convolution/operators/make_operator.hpp), which it cannot sit beside:
/// stresses build on convolution/. The front ends build every stress operator through it, after
/// the memory check of estimated_stress_bytes. Throws as the constructor does.
std::unique_ptr<StressOperator> make_stress_operator(const Grid& grid, const LayerStack& body,
                                                     std::vector<double> depths,
                                                     const StressOperatorOptions& options = {});

}  // namespace coatfft
