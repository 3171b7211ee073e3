#pragma once
// The contact solver (contact/contact_solver.hpp) on fields distributed in row slabs over the
// ranks of a distributed operator (docs/scale.md): the same iteration, each pass over this rank's
// cells with its sums, counts and maxima combined over the ranks in rank order, the half-space
// preconditioner applied by the slab transform, the load-controlled start's level found without
// gathering the heights. Heights, pressures, displacements and gaps are this rank's rows; the
// result's numbers (load, area, iterations, status) are the whole grid's, the same on every rank.
// Every solve is collective. No nested start yet (ContactOptions::nested_start is ignored).
#include <memory>

#include "../contact/contact_solver.hpp"
#include "distributed_operator.hpp"

namespace coatfft {

/// A solver bound to `op` (which must outlive it), on op's communicator and slabs.
std::unique_ptr<ContactSolver> distributed_contact_solver(DistributedOperator& op,
                                                          ContactOptions options = {});

}  // namespace coatfft
