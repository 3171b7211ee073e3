#include "convolution/kernels/periodic_kernel.hpp"

#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/detail/periodic_kernel_parts.hpp"
#include "core/detail/parallel_for.hpp"

namespace coatfft {

namespace {

// The lattice part's spectrum M on the half lattice 0 <= i <= nx/2 (FFTW's c2r layout). M is even
// in j (the aliases q and -q pair up), and on square cells of a square period symmetric in i and
// j: it is evaluated for 0 <= j <= ny/2 (and j <= i when square), a quarter or an eighth of the
// half lattice, and mirrored.
std::vector<double> spectrum(const Grid& g, const detail::PeriodicKernelParts& parts, int threads) {
  const std::ptrdiff_t hx = g.nx() / 2 + 1, hy = g.ny() / 2;
  const bool square = g.nx() == g.ny() && g.dx() == g.dy();
  std::vector<double> m(static_cast<std::size_t>(hx * g.ny()), 0.0);
  const auto at = [&](std::ptrdiff_t i, std::ptrdiff_t j) -> double& {
    return m[static_cast<std::size_t>(j * hx + i)];
  };
  detail::parallel_for(0, hy + 1, threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = square ? j : 0; i < hx; ++i) at(i, j) = parts.spectrum(i, j);
  });
  for (std::ptrdiff_t j = 0; j <= hy; ++j) {
    if (square)
      for (std::ptrdiff_t i = 0; i < j; ++i) at(i, j) = at(j, i);
    if (j > 0 && j < hy)
      for (std::ptrdiff_t i = 0; i < hx; ++i) at(i, g.ny() - j) = at(i, j);
  }
  return m;
}

// K_F(i, j) = (1/(nx ny)) sum_m M_m exp(i k_m . d) over the whole lattice (M real and even).
Field to_space(const Grid& g, const std::vector<double>& m) {
  const std::ptrdiff_t hx = g.nx() / 2 + 1;
  FftwComplexBuffer in(static_cast<std::size_t>(hx * g.ny()));
  for (std::size_t n = 0; n < m.size(); ++n) as_complex(in.data())[n] = m[n];
  FftwRealBuffer out(static_cast<std::size_t>(g.nx() * g.ny()));
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_dft_c2r_2d(int(g.ny()), int(g.nx()), in.data(), out.data(),
                                FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  });
  plan.execute();
  return Eigen::Map<const Field>(out.data(), g.nx(), g.ny()) / double(g.nx() * g.ny());
}

}  // namespace

Field periodic_influence_kernel(const Grid& g, const Frf& frf, const PeriodicKernelOptions& o) {
  const detail::PeriodicKernelParts parts(g, frf, o);
  Field k = to_space(g, spectrum(g, parts, o.threads));
  const std::ptrdiff_t hx = g.nx() / 2, hy = g.ny() / 2;
  Field quarter(hx + 1, hy + 1);
  // On square cells of a square period the part is symmetric in its offsets (x and y swap with
  // the images and the cell): an octant is computed and mirrored.
  const bool square = g.nx() == g.ny() && g.dx() == g.dy();
  detail::parallel_for(0, hy + 1, o.threads, [&](std::ptrdiff_t j) {
    for (std::ptrdiff_t i = square ? j : 0; i <= hx; ++i) quarter(i, j) = parts.real_space(i, j);
  });
  if (square)
    for (std::ptrdiff_t j = 0; j <= hy; ++j)
      for (std::ptrdiff_t i = 0; i < j; ++i) quarter(i, j) = quarter(j, i);
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
      k(i, j) += quarter(i <= hx ? i : g.nx() - i, j <= hy ? j : g.ny() - j);
  // The k = 0 term is left out: the real-space part's integral over the plane is removed with the
  // mean (the lattice part has none: every alias of k = 0 has S = 0).
  return k - k.mean();
}

}  // namespace coatfft
