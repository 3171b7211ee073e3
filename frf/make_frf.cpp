#include <memory>

#include "frf/coated_frf.hpp"
#include "frf/frf.hpp"
#include "frf/half_space_frf.hpp"
#include "frf/multilayer_frf.hpp"
#include "layers/layer_stack.hpp"

namespace coatfft {

std::unique_ptr<Frf> make_frf(const LayerStack& stack) {
  const auto& coatings = stack.coatings();
  if (coatings.empty()) return std::make_unique<HalfSpaceFrf>(stack.substrate());
  if (coatings.size() == 1) {
    const Coating& c = coatings.front();
    return std::make_unique<CoatedFrf>(c.material, c.thickness, stack.substrate(),
                                       c.interface_below);
  }
  return std::make_unique<MultilayerFrf>(stack);
}

}  // namespace coatfft
