#pragma once
// The ranks of a Communicator as the contact solver sees them (contact/detail/solver_ranks.hpp):
// its gathers, this rank's rows, the preconditioner of the distributed fields.
#include "contact/detail/solver_ranks.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"

namespace coatfft::detail {

class CommunicatorRanks final : public SolverRanks {
 public:
  CommunicatorRanks(const Communicator& comm, const Slab& slab) : comm_(comm), slab_(slab) {}
  int count() const override { return comm_.size(); }
  void all_gather(const void* mine, std::size_t size, void* all) const override {
    comm_.all_gather(mine, size, all);
  }
  std::ptrdiff_t first_row() const override { return slab_.y0; }
  std::ptrdiff_t rows() const override { return slab_.rows; }
  /// The half-space preconditioner on the slab transform (distributed_contact.cpp).
  std::unique_ptr<Preconditioner> preconditioner(const SurfaceOperator& op, int threads,
                                                 Planning planning) const override;
  /// `op` is a DistributedOperator on the same communicator (distributed_contact.cpp).
  std::shared_ptr<const SolverRanks> of(const SurfaceOperator& op) const override;

 private:
  Communicator comm_;
  Slab slab_;
};

}  // namespace coatfft::detail
