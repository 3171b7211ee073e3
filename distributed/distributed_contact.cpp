#include "distributed/distributed_contact.hpp"

#include <memory>
#include <utility>
#include <vector>

#include "contact/detail/fourier_preconditioner.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "distributed/detail/communicator_ranks.hpp"
#include "distributed/detail/slab_fft.hpp"
#include "distributed/distributed_periodic_operator.hpp"

namespace coatfft {

namespace {

// The half-space preconditioner (contact/detail/fourier_preconditioner.hpp) on this rank's rows:
// its symbol on this rank's half-spectrum columns, applied by the slab transform.
class SlabPreconditioner final : public detail::Preconditioner {
 public:
  // `fft`: the operator's slab transform, shared, or one of its own.
  SlabPreconditioner(std::shared_ptr<detail::SlabFft> fft, const Grid& grid)
      : fft_(std::move(fft)) {
    const Slab& s = fft_->slab();
    const double norm = 1.0 / static_cast<double>(grid.nb_cells());
    sigma_.resize(static_cast<std::size_t>(s.columns * s.ny));
    for (std::ptrdiff_t c = 0; c < s.columns; ++c)
      for (std::ptrdiff_t j = 0; j < s.ny; ++j)
        sigma_[static_cast<std::size_t>(c * s.ny + j)] =
            detail::preconditioner_symbol(grid, s.kx0 + c, j, norm);
  }
  void apply(double* z) override {
    fft_->forward(z);
    std::complex<double>* spectrum = fft_->spectrum();
    for (std::size_t n = 0; n < sigma_.size(); ++n) spectrum[n] *= sigma_[n];
    fft_->inverse(z);
  }

 private:
  std::shared_ptr<detail::SlabFft> fft_;
  std::vector<double> sigma_;
};

}  // namespace

std::unique_ptr<detail::Preconditioner> detail::CommunicatorRanks::preconditioner(
    const SurfaceOperator& op, int threads, Planning planning) const {
  // The periodic operator's slab transform is shared (its two half spectra, 16 bytes a cell of
  // the rank: docs/scale.md, "Memory per cell"); a DC-FFT's transforms are of its padded lattice.
  const Grid& grid = op.grid();
  if (const auto* periodic = dynamic_cast<const DistributedPeriodicOperator*>(&op))
    return std::make_unique<SlabPreconditioner>(periodic->slab_fft(), grid);
  return std::make_unique<SlabPreconditioner>(
      std::make_shared<detail::SlabFft>(comm_, grid.nx(), grid.ny(), planning, threads), grid);
}

std::shared_ptr<const detail::SolverRanks> detail::CommunicatorRanks::of(
    const SurfaceOperator& op) const {
  const auto& distributed = dynamic_cast<const DistributedOperator&>(op);
  return std::make_shared<CommunicatorRanks>(comm_, distributed.slab());
}

std::unique_ptr<ContactSolver> distributed_contact_solver(DistributedOperator& op,
                                                          ContactOptions options) {
  return std::make_unique<ContactSolver>(
      op, std::move(options),
      std::make_shared<detail::CommunicatorRanks>(op.communicator(), op.slab()));
}

}  // namespace coatfft
