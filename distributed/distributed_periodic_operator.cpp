#include "distributed/distributed_periodic_operator.hpp"

#include <memory>
#include <vector>

#include "convolution/kernels/detail/periodic_kernel_parts.hpp"
#include "core/detail/parallel_for.hpp"
#include "core/error.hpp"
#include "distributed/detail/slab_fft.hpp"

namespace coatfft {

struct DistributedPeriodicOperator::Transforms {
  std::shared_ptr<detail::SlabFft> fft;  // shared with a contact solver's preconditioner
  std::vector<double> multiplier;  // this rank's columns of the kernel's real spectrum, over nx ny
};

namespace {

// The kernel's spectrum in the serial operator's steps (PeriodicOperator with
// periodic_influence_kernel): K = IDFT(M)/(nx ny) + real space, less its mean; DFT(K)/(nx ny).
std::vector<double> kernel_spectrum(const Communicator& comm, detail::SlabFft& fft, const Grid& g,
                                    const Frf& frf, const PeriodicKernelOptions& o) {
  const detail::PeriodicKernelParts parts(g, frf, o);
  const Slab& s = fft.slab();
  std::complex<double>* spectrum = fft.spectrum();
  detail::parallel_for(0, s.columns, o.threads, [&](std::ptrdiff_t c) {
    for (std::ptrdiff_t j = 0; j < s.ny; ++j) spectrum[c * s.ny + j] = parts.spectrum(s.kx0 + c, j);
  });
  Field k = s.field();
  fft.inverse(k.data());
  const double cells = static_cast<double>(g.nx() * g.ny());
  k /= cells;
  // The real-space part is even in x: half a row evaluated, mirrored (the serial kernel folds
  // both axes; a rank's rows need not hold a row's mirror in y).
  detail::parallel_for(0, s.rows, o.threads, [&](std::ptrdiff_t r) {
    for (std::ptrdiff_t i = 0; i <= s.nx / 2; ++i) {
      const double v = parts.real_space(i, s.y0 + r);
      k(i, r) += v;
      if (i > 0 && i < s.nx / 2) k(s.nx - i, r) += v;
    }
  });
  k -= comm.sum(k.sum()) / cells;
  fft.forward(k.data());
  std::vector<double> m(static_cast<std::size_t>(s.columns * s.ny));
  for (std::size_t n = 0; n < m.size(); ++n) m[n] = (1.0 / cells) * spectrum[n].real();
  return m;
}

}  // namespace

DistributedPeriodicOperator::~DistributedPeriodicOperator() = default;

DistributedPeriodicOperator::DistributedPeriodicOperator(const Communicator& comm, const Grid& grid,
                                                         const Frf& frf,
                                                         const PeriodicKernelOptions& kernel,
                                                         Planning planning, int threads,
                                                         Method method)
    : DistributedOperator(comm, grid), method_(method) {
  COATFFT_REQUIRE(threads >= 1, "DistributedPeriodicOperator: threads = ", threads,
                  " must be >= 1");
  COATFFT_REQUIRE(grid.nx() % 2 == 0 && grid.ny() % 2 == 0,
                  "DistributedPeriodicOperator: nx = ", grid.nx(), " and ny = ", grid.ny(),
                  " must be even");
  t_ = std::make_unique<Transforms>(Transforms{
      std::make_shared<detail::SlabFft>(comm, grid.nx(), grid.ny(), planning, threads), {}});
  t_->multiplier = kernel_spectrum(comm, *t_->fft, grid, frf, kernel);
}

const Slab& DistributedPeriodicOperator::slab() const {
  return t_->fft->slab();
}

const std::shared_ptr<detail::SlabFft>& DistributedPeriodicOperator::slab_fft() const {
  return t_->fft;
}

void DistributedPeriodicOperator::apply(const Field& pressure, Field& displacement) {
  // An application's only collectives besides its transposes. Every displacement sums every
  // mode, each mode every cell of every rank: a value that is not finite anywhere reaches each
  // rank's first displacement, which is checked instead of every pressure (PeriodicOperator's
  // rule).
  check_shape(pressure, displacement, "DistributedPeriodicOperator");
  const Slab& s = slab();
  displacement.resize(s.nx, s.rows);
  t_->fft->forward(pressure.data());
  std::complex<double>* spectrum = t_->fft->spectrum();
  for (std::size_t n = 0; n < t_->multiplier.size(); ++n) spectrum[n] *= t_->multiplier[n];
  t_->fft->inverse(displacement.data());
  check_displacement(displacement, "DistributedPeriodicOperator");
}

double DistributedPeriodicOperator::communication_seconds() const {
  return t_->fft->transpose_seconds();
}

}  // namespace coatfft
