#pragma once
// What a solve on an Operator needs from the module's solving functions (solve_contact,
// solve_sliding, solve_sweep, solve_partial_slip): the solver's options, the check that a body is
// the operator's, and that body's 3 x 3 surface response on the operator's grid and boundary.
#include <memory>

#include "contact/contact_solver.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "layers/layer_stack.hpp"
#include "operator.hpp"

namespace coatfft::python {

/// The contact solver's options for a solve on `op`: its threads, the approach reported when the
/// operator knows g(0); InvalidArgument (naming `what`) for approach control without it.
ContactOptions contact_options(const Operator& op, bool approach_control, double tolerance,
                               int max_iterations, bool preconditioned, const char* what);

/// Refuses (InvalidArgument, naming `what`) a body that is not the one `op` was made for: the
/// tractions' response of one body must not be added to the normal displacement of another.
void require_operator_body(const Operator& op, const LayerStack& body, const char* what);

/// The 3 x 3 surface response of `body` on `op`'s grid, periodic when `op` is, its lattices on
/// `threads` threads. The caller holds op.lock().
std::shared_ptr<CerrutiOperator> surface_response(Operator& op, const LayerStack& body,
                                                  int threads);

}  // namespace coatfft::python
