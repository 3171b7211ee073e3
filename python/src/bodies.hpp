#pragma once
// What Python may pass as a body: a LayerStack, a Material (a homogeneous half-space) or an Frf
// (UserFrf, TabulatedFrf). Every function that takes a body reads it here.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"

namespace coatfft::python {

struct Body {
  std::optional<LayerStack> stack;  ///< a layered body, or
  std::shared_ptr<const Frf> frf;   ///< a body known by its FRF alone

  /// The FRF of the body: its own, or the exact one of the stack (frf/make_frf).
  std::shared_ptr<const Frf> response() const;
};

/// `object` as a Body; TypeError naming the accepted types otherwise. `what` names the argument.
Body body_from_object(pybind11::handle object, const char* what = "body");

/// The layers of `body_object` (a LayerStack or a Material), which `who` needs for `why`: an Frf
/// is refused (ValueError).
LayerStack layers_of(pybind11::handle body_object, const std::string& who, const char* why);

}  // namespace coatfft::python
