#include "layers/layer_stack.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace coatfft {

namespace {

// Shortest round-trip form ("-1e-06"), so messages show the value the user typed.
std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

LayerStack::LayerStack(Material substrate) : substrate_(substrate) {}

LayerStack::LayerStack(std::vector<Coating> coatings, Material substrate)
    : coatings_(std::move(coatings)), substrate_(substrate) {
  COATFFT_REQUIRE(coatings_.size() <= max_coatings, "LayerStack: ", coatings_.size(),
                  " coatings, but at most ", max_coatings, " are allowed");
  for (std::size_t i = 0; i < coatings_.size(); ++i) {
    const double h = coatings_[i].thickness;
    COATFFT_REQUIRE(std::isfinite(h) && h > 0, "LayerStack: coating ", i + 1,
                    ": thickness = ", shortest(h), " m, but the thickness must be finite and > 0");
  }
  double depth = 0.0;
  for (const Coating& c : coatings_) interfaces_.push_back(depth += c.thickness);
}

bool LayerStack::all_bonded() const {
  for (const Coating& c : coatings_)
    if (c.interface_below != Interface::bonded) return false;
  return true;
}

double LayerStack::total_thickness() const {
  return interfaces_.empty() ? 0.0 : interfaces_.back();
}

DepthLocation LayerStack::locate(double depth, InterfaceSide side) const {
  COATFFT_REQUIRE(std::isfinite(depth) && depth >= 0, "LayerStack: depth = ", shortest(depth),
                  " m, but depths must be finite and >= 0");
  // The interfaces within the tolerance of the depth are [lo, hi); the ones before lo lie above.
  const double tol = interface_tolerance * depth;
  const auto lo = std::lower_bound(interfaces_.begin(), interfaces_.end(), depth - tol);
  const auto hi = std::upper_bound(lo, interfaces_.end(), depth + tol);
  const auto above = static_cast<std::size_t>(lo - interfaces_.begin());
  if (lo == hi) return {above, false, depth};
  if (side == InterfaceSide::above) return {above, true, *lo};
  return {static_cast<std::size_t>(hi - interfaces_.begin()), true, *(hi - 1)};
}

}  // namespace coatfft
