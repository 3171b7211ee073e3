#include "layers/layer_stack.hpp"

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
}

bool LayerStack::all_bonded() const {
  for (const Coating& c : coatings_)
    if (c.interface_below != Interface::bonded) return false;
  return true;
}

double LayerStack::total_thickness() const {
  double sum = 0.0;
  for (const auto& coating : coatings_) sum += coating.thickness;
  return sum;
}

}  // namespace coatfft
