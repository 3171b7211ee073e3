#pragma once
// The space part of Ewald's (1921) split of a periodic surface kernel (periodic_kernel.cpp,
// periodic_traction_kernels.cpp): the cell integral of the smooth kernel whose complement is
// summed on the lattice, by a Gauss-Legendre rule whose order follows the kernel's variation over
// a cell (private: not installed).
#include <algorithm>

#include "../../core/detail/gauss_legendre.hpp"

namespace coatfft::detail {

/// \iint f over the dx x dy cell centred at (x, y) by an N x N Gauss-Legendre rule.
template <int N, class Kernel>
double gauss_cell_integral(const Kernel& f, double x, double y, double dx, double dy) {
  const auto& rule = gauss_legendre<N>();
  double s = 0.0;
  for (int p = 0; p < N; ++p)
    for (int q = 0; q < N; ++q)
      s += rule.weights[p] * rule.weights[q] *
           f(x - 0.5 * dx * rule.nodes[p], y - 0.5 * dy * rule.nodes[q]);
  return 0.25 * dx * dy * s;
}

/// The same for a kernel smooth on the length 1/alpha [m] (entire, varying like exp(-alpha^2
/// r^2)): with t = alpha max(dx, dy), an m-point rule errs by about (t/2)^(2m) of the integral,
/// below 1e-16 with 2 points for t <= 1e-4, 4 points for t <= 0.02 (large grids: t = 6/n), 8 up to
/// t = 1, 16 beyond.
template <class Kernel>
double smooth_cell_integral(const Kernel& f, double alpha, double x, double y, double dx,
                            double dy) {
  const double t = alpha * std::max(dx, dy);
  if (t <= 1e-4) return gauss_cell_integral<2>(f, x, y, dx, dy);
  if (t <= 0.02) return gauss_cell_integral<4>(f, x, y, dx, dy);
  if (t <= 1.0) return gauss_cell_integral<8>(f, x, y, dx, dy);
  return gauss_cell_integral<16>(f, x, y, dx, dy);
}

}  // namespace coatfft::detail
