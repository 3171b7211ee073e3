#pragma once
// A check that each rank makes on its own (reading its scene, its files, its machine's memory)
// before the ranks' next collective step: a rank that refused alone would leave the others waiting
// in that step for ever, and itself in MPI_Finalize. Here every rank learns of any rank's refusal
// and refuses with it.
#include <functional>

#include "../communicator.hpp"

namespace coatfft {

/// Runs `step` on every rank of `comm`; when it throws on any rank, throws on every rank the
/// first refusing rank's exception (InvalidArgument stays InvalidArgument, anything else becomes
/// Error), its message preceded by "rank R: " unless every rank refused with the same message.
/// Collective.
void agreed_refusal(const Communicator& comm, const std::function<void()>& step);

}  // namespace coatfft
