#include "convolution/kernels/split_kernel/detail/tables.hpp"

#include <gsl/gsl_sf_bessel.h>

#include "core/detail/parallel_for.hpp"

namespace coatfft::detail::split {

void fill_lower_triangle(double* a, std::ptrdiff_t n, std::ptrdiff_t stride, int threads) {
  constexpr std::ptrdiff_t tile = 64;
  detail::parallel_for(0, (n + tile - 1) / tile, threads, [&](std::ptrdiff_t tj) {
    const std::ptrdiff_t j_end = std::min(n, (tj + 1) * tile);
    for (std::ptrdiff_t ti = 0; ti <= tj * tile; ti += tile)
      for (std::ptrdiff_t j = tj * tile; j < j_end; ++j)
        for (std::ptrdiff_t i = ti; i < std::min(j, ti + tile); ++i)
          a[j * stride + i] = a[i * stride + j];
  });
}

EvenTable hankel_table(const std::vector<double>& kw, const std::vector<double>& kn, double dr,
                       double r_max, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(std::ceil(r_max / dr)) + 4;
  const double x_max = (kn.empty() ? 0.0 : kn.back()) * dr * static_cast<double>(n);
  constexpr double h = 1.0 / 64.0;
  const auto nj = static_cast<std::ptrdiff_t>(std::min(std::ceil(x_max / h), 65536.0)) + 4;
  std::vector<double> j0(static_cast<std::size_t>(nj));
  detail::parallel_for(0, nj, threads, [&](std::ptrdiff_t i) {
    j0[static_cast<std::size_t>(i)] = gsl_sf_bessel_J0(h * static_cast<double>(i));
  });
  const EvenTable bessel(j0, h);
  const double x_table = h * static_cast<double>(nj - 4);
  std::vector<double> g(static_cast<std::size_t>(n));
  detail::parallel_for(0, n, threads, [&](std::ptrdiff_t i) {
    const double r = dr * static_cast<double>(i);
    double sum = 0.0;
    for (std::size_t j = 0; j < kn.size(); ++j) {
      const double x = kn[j] * r;
      sum += kw[j] * (x <= x_table ? bessel(x) : gsl_sf_bessel_J0(x));
    }
    g[static_cast<std::size_t>(i)] = sum;
  });
  return EvenTable(g, dr);
}

}  // namespace coatfft::detail::split
