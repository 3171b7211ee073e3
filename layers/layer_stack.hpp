#pragma once
// A layered elastic half-space: zero or more coatings, listed from the top surface down, on a
// homogeneous substrate. A stack is data; its physics (FRFs) lives in frf/.
#include <cstddef>
#include <limits>
#include <vector>

#include "../materials/material.hpp"

namespace coatfft {

/// Condition on the interface between a coating and the medium below it.
enum class Interface {
  bonded,        ///< perfect adhesion: displacements and tractions continuous
  frictionless,  ///< full slip: normal displacement and normal stress continuous, zero shear
};

/// Which medium a depth on an interface belongs to: the one above it or the one below.
enum class InterfaceSide { above, below };

/// Where a depth lies in a stack (LayerStack::locate).
struct DepthLocation {
  /// The medium: coating i (0-based, top first), or coatings().size() for the substrate.
  std::size_t layer;
  /// Whether the depth is an interface's (within LayerStack::interface_tolerance).
  bool at_interface;
  /// The depth to evaluate at [m]: the interface's own (interface_depths()) when at_interface,
  /// else the depth given.
  double depth;
};

struct Coating {
  Material material;
  double thickness;  ///< [m], finite and > 0
  Interface interface_below = Interface::bonded;
};

class LayerStack {
 public:
  /// At most this many coatings (a guard against runaway input, not a numerical limit).
  static constexpr std::size_t max_coatings = 64;

  /// A homogeneous half-space.
  explicit LayerStack(Material substrate);
  /// Coatings top first; validated on construction with messages naming the coating (1-based).
  LayerStack(std::vector<Coating> coatings, Material substrate);

  const Material& substrate() const { return substrate_; }
  const std::vector<Coating>& coatings() const { return coatings_; }
  bool is_homogeneous() const { return coatings_.empty(); }
  /// Whether every interface is bonded (true for a homogeneous body).
  bool all_bonded() const;
  /// Sum of coating thicknesses [m] (0 for a homogeneous body).
  double total_thickness() const;

  /// Relative tolerance [-] within which a depth is an interface's: 256 DBL_EPSILON of the
  /// depth. An interface depth is a running sum h_1 + ... + h_i of thicknesses each rounded on
  /// input; a sum of n positive terms carries at most (n - 1) u relative rounding, u = eps/2
  /// (Higham 2002, "Accuracy and Stability of Numerical Algorithms", section 4.2), so under
  /// 32 eps for the max_coatings = 64 coatings, and a depth the user computes or types (a decimal
  /// rounded once, or depth_max k / nz) a few eps more. 256 eps leaves a margin and is still
  /// 6e-14 of the depth: no two physically distinct planes are that close.
  static constexpr double interface_tolerance = 256.0 * std::numeric_limits<double>::epsilon();

  /// Depths [m] of the interfaces, top first: the running sums h_1, h_1 + h_2, ... (the last is
  /// total_thickness()); empty for a homogeneous body. Every depth compared with an interface's
  /// is compared with these, through locate().
  const std::vector<double>& interface_depths() const { return interfaces_; }

  /// The medium holding `depth` [m] (finite, >= 0): a depth within interface_tolerance of an
  /// interface depth is that interface and lies in the medium `side` names; the surface z = 0
  /// lies in the first medium. Should interfaces closer than the tolerance both match, `below`
  /// takes the medium under the deepest, `above` the one over the shallowest. InvalidArgument on
  /// a bad depth. O(log n).
  DepthLocation locate(double depth, InterfaceSide side) const;

 private:
  std::vector<Coating> coatings_;
  Material substrate_;
  std::vector<double> interfaces_;  // interface_depths()
};

}  // namespace coatfft
