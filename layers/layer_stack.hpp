#pragma once
// A layered elastic half-space: zero or more coatings, listed from the top surface down, on a
// homogeneous substrate. A stack is data; its physics (FRFs) lives in frf/.
#include <cstddef>
#include <vector>

#include "../materials/material.hpp"

namespace coatfft {

/// Condition on the interface between a coating and the medium below it.
enum class Interface {
  bonded,        ///< perfect adhesion: displacements and tractions continuous
  frictionless,  ///< full slip: normal displacement and normal stress continuous, zero shear
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

 private:
  std::vector<Coating> coatings_;
  Material substrate_;
};

}  // namespace coatfft
