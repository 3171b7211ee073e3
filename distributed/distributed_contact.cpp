#include "distributed/distributed_contact.hpp"

#include <vector>

#include "contact/detail/fourier_preconditioner.hpp"
#include "contact/detail/solver_ranks.hpp"
#include "distributed/detail/communicator_ranks.hpp"
#include "distributed/detail/slab_fft.hpp"

namespace coatfft {

namespace {

// The half-space preconditioner (contact/detail/fourier_preconditioner.hpp) on this rank's rows:
// its symbol on this rank's half-spectrum columns, applied by the slab transform.
class SlabPreconditioner final : public detail::Preconditioner {
 public:
  SlabPreconditioner(const Communicator& comm, const Grid& grid, int threads, Planning planning)
      : fft_(comm, grid.nx(), grid.ny(), planning, threads) {
    const Slab& s = fft_.slab();
    const double norm = 1.0 / static_cast<double>(grid.nb_cells());
    sigma_.resize(static_cast<std::size_t>(s.columns * s.ny));
    for (std::ptrdiff_t c = 0; c < s.columns; ++c)
      for (std::ptrdiff_t j = 0; j < s.ny; ++j)
        sigma_[static_cast<std::size_t>(c * s.ny + j)] =
            detail::preconditioner_symbol(grid, s.kx0 + c, j, norm);
  }
  void apply(double* z) override {
    fft_.forward(z);
    std::complex<double>* spectrum = fft_.spectrum();
    for (std::size_t n = 0; n < sigma_.size(); ++n) spectrum[n] *= sigma_[n];
    fft_.inverse(z);
  }

 private:
  detail::SlabFft fft_;
  std::vector<double> sigma_;
};

}  // namespace

std::unique_ptr<detail::Preconditioner> detail::CommunicatorRanks::preconditioner(
    const Grid& grid, int threads, Planning planning) const {
  return std::make_unique<SlabPreconditioner>(comm_, grid, threads, planning);
}

std::unique_ptr<ContactSolver> distributed_contact_solver(DistributedOperator& op,
                                                          ContactOptions options) {
  return std::make_unique<ContactSolver>(
      op, std::move(options),
      std::make_shared<detail::CommunicatorRanks>(op.communicator(), op.slab()));
}

}  // namespace coatfft
