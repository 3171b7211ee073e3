#pragma once
// The stresses a [stress] scene asks for (docs/stress.md): the planes at its depths, the section
// y = 0, the planes of each interface seen from both sides, and the summary's "stress" object
// (largest von Mises, principal tensile and Tresca stress per medium and overall, the largest
// shear stress on each interface), under the scene's pressure. The maxima are those of the values
// written: the depths' and the interfaces' planes, and the section's row.
#include <nlohmann/json.hpp>
#include <vector>

#include "core/types.hpp"
#include "scene/progress_observer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_pressure.hpp"

namespace coatfft::scene {

/// The arrays compute_stress assembles (the summary's maxima are computed whatever they are):
/// those of the [output] fields a run writes; every one by default.
struct StressArrays {
  bool stress = true, von_mises = true;                 ///< the depths' planes
  bool section = true, section_von_mises = true;        ///< the section's rows
  bool interfaces = true, interfaces_von_mises = true;  ///< the interfaces' planes
};

/// What [stress] computes. Arrays are C-order, ready for .npy; one not asked for is empty.
struct StressRun {
  std::vector<double> stress;     ///< (n_depths, 6, ny, nx) [Pa]; empty without depths
  std::vector<double> von_mises;  ///< (n_depths, ny, nx) [Pa]
  std::vector<double> section;    ///< (nz, 6, nx) [Pa] on the row nearest y = 0; empty without
  std::vector<double> section_von_mises;  ///< (nz, nx) [Pa]
  /// (n_interfaces, 2, 6, ny, nx) [Pa]: each interface of the body, top first, in the medium
  /// above it (side 0) and below it (side 1); empty for a homogeneous body
  std::vector<double> interfaces;
  std::vector<double> interfaces_von_mises;  ///< (n_interfaces, 2, ny, nx) [Pa]
  /// The arrays' leading sizes: n_depths, nz (the section's rows), n_interfaces.
  std::size_t depth_planes = 0, section_rows = 0, interface_count = 0;
  nlohmann::json summary;  ///< summary.json's "stress"
};

/// The stresses of `spec` in the body `body` on `grid` under `pressure` and the tractions `q`
/// (each (nx, ny) [Pa]), with the library's StressOperator on `threads` threads, its steps (the
/// planes' kernels, their maxima) reported to `progress`. Throws InvalidArgument if a result is
/// not finite.
StressRun compute_stress(const StressSpec& spec, const LayerStack& body, const Grid& grid,
                         const Field& pressure, const Tractions& q, int threads,
                         ProgressObserver& progress, const StressArrays& arrays = {});

}  // namespace coatfft::scene
