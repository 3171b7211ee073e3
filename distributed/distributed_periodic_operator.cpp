#include "distributed/distributed_periodic_operator.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "convolution/kernels/detail/coarse_kernel.hpp"
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

// DFT(K)/(nx ny) on this rank's columns from its rows of the kernel K (`kernel` is overwritten):
// real, the kernel being even.
std::vector<double> kernel_multiplier(detail::SlabFft& fft, Field& kernel) {
  const Slab& s = fft.slab();
  const double cells = static_cast<double>(s.nx * s.ny);
  fft.forward(kernel.data());
  const std::complex<double>* spectrum = fft.spectrum();
  std::vector<double> m(static_cast<std::size_t>(s.columns * s.ny));
  for (std::size_t n = 0; n < m.size(); ++n) m[n] = (1.0 / cells) * spectrum[n].real();
  return m;
}

// The fine kernel's row y0 - 1 (modulo ny) for this rank's slab: the last row of the nearest
// rank before it that holds rows (gathered from every rank's last row; a rank without rows
// sends its row index as -1).
std::vector<double> row_before(const Communicator& comm, const Slab& s, const Field& kernel) {
  std::vector<double> mine(static_cast<std::size_t>(s.nx + 1), 0.0);
  mine[0] = s.rows > 0 ? static_cast<double>(s.y0 + s.rows - 1) : -1.0;
  if (s.rows > 0) std::copy_n(&kernel(0, s.rows - 1), s.nx, mine.begin() + 1);
  std::vector<double> all(mine.size() * static_cast<std::size_t>(comm.size()));
  comm.all_gather(mine.data(), mine.size() * sizeof(double), all.data());
  const double wanted = static_cast<double>(s.y0 == 0 ? s.ny - 1 : s.y0 - 1);
  for (std::size_t r = 0; r < static_cast<std::size_t>(comm.size()); ++r)
    if (all[r * mine.size()] == wanted)
      return {all.begin() + std::ptrdiff_t(r * mine.size() + 1),
              all.begin() + std::ptrdiff_t((r + 1) * mine.size())};
  return std::vector<double>(static_cast<std::size_t>(s.nx), 0.0);  // no rows here: not read
}

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
  return kernel_multiplier(fft, k);
}

}  // namespace

DistributedPeriodicOperator::~DistributedPeriodicOperator() = default;

DistributedPeriodicOperator::DistributedPeriodicOperator(const Communicator& comm, const Grid& grid,
                                                         const Frf& frf,
                                                         const PeriodicKernelOptions& kernel,
                                                         Planning planning, int threads,
                                                         Method method)
    : DistributedOperator(comm, grid), method_(method), threads_(threads) {
  COATFFT_REQUIRE(threads >= 1, "DistributedPeriodicOperator: threads = ", threads,
                  " must be >= 1");
  COATFFT_REQUIRE(grid.nx() % 2 == 0 && grid.ny() % 2 == 0,
                  "DistributedPeriodicOperator: nx = ", grid.nx(), " and ny = ", grid.ny(),
                  " must be even");
  t_ = std::make_unique<Transforms>(Transforms{
      std::make_shared<detail::SlabFft>(comm, grid.nx(), grid.ny(), planning, threads), {}});
  t_->multiplier = kernel_spectrum(comm, *t_->fft, grid, frf, kernel);
}

DistributedPeriodicOperator::DistributedPeriodicOperator(const Communicator& comm, const Grid& grid,
                                                         std::shared_ptr<detail::SlabFft> fft,
                                                         Field kernel_rows, int threads,
                                                         Method method)
    : DistributedOperator(comm, grid), method_(method), threads_(threads) {
  t_ = std::make_unique<Transforms>(Transforms{std::move(fft), {}});
  t_->multiplier = kernel_multiplier(*t_->fft, kernel_rows);
}

std::unique_ptr<SurfaceOperator> DistributedPeriodicOperator::coarsened() {
  const Grid& g = grid();
  const Slab& s = slab();
  const Communicator& comm = communicator();
  if (!comm.all(g.nx() % 2 == 0 && g.ny() % 2 == 0 && s.y0 % 2 == 0 && s.rows % 2 == 0))
    return nullptr;
  const Grid coarse(g.nx() / 2, g.ny() / 2, g.lx(), g.ly());
  // The coarse rows of this rank's pairs must be FFTW's coarse slab for it (asked before any
  // transform is planned).
  const Slab coarse_slab = slab_of(comm, coarse.nx(), coarse.ny());
  if (!comm.all(coarse_slab.y0 == s.y0 / 2 && coarse_slab.rows == s.rows / 2)) return nullptr;
  auto fft = std::make_shared<detail::SlabFft>(comm, coarse.nx(), coarse.ny(), Planning::estimate,
                                               threads_);
  const Field kernel = unit_response();
  const std::vector<double> before = row_before(comm, s, kernel);
  Field rows = s.rows > 0 ? detail::coarse_periodic_kernel_rows(kernel, before.data())
                          : Field(coarse.nx(), 0);
  return std::unique_ptr<SurfaceOperator>(new DistributedPeriodicOperator(
      comm, coarse, std::move(fft), std::move(rows), threads_, method_));
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
