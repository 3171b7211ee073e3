#pragma once
// Ewald's (1921) split of a periodic surface kernel, as periodic_kernel.cpp and
// periodic_traction_kernels.cpp make it (private: not installed): the split length, the lattice
// of the period's wavevectors with their aliases, and the space part's cell integrals of the
// smooth kernel whose complement is summed on the lattice.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "../../../core/detail/gauss_legendre.hpp"
#include "../../../core/grid.hpp"

namespace coatfft::detail {

/// erfc(6.5) = 3.8e-20: the Ewald sums' terms beyond are below any tolerance of the kernels.
inline constexpr double kEwaldErfcCut = 6.5;

/// The split's inverse length [1/m]: 6/min(lx, ly) keeps the space part within the 3 x 3 nearest
/// images (the next are >= 9/alpha away: erfc(9) = 4e-37) and the lattice part within
/// 13 alpha = 78/min(lx, ly).
inline double ewald_alpha(const Grid& g) {
  return 6.0 / std::min(g.lx(), g.ly());
}

/// The half lattice of the period's wavevectors (FFTW's c2r layout: 0 <= i <= nx/2, j the signed
/// frequency), each with its aliases up to order (px, py), far enough for the larger of the Ewald
/// part's reach k_ewald and a remainder's k_rest.
struct EwaldLattice {
  std::ptrdiff_t hx, ny;
  double dkx, dky, k_ewald, k_rest;
  int px, py;
};

inline EwaldLattice ewald_lattice(const Grid& g, double alpha, double k_rest) {
  using std::numbers::pi;
  EwaldLattice l{g.nx() / 2 + 1,
                 g.ny(),
                 2.0 * pi / g.lx(),
                 2.0 * pi / g.ly(),
                 2.0 * alpha * kEwaldErfcCut,
                 k_rest,
                 0,
                 0};
  const double k_max = std::max(l.k_ewald, l.k_rest);
  l.px = static_cast<int>(std::ceil(k_max * g.dx() / (2.0 * pi))) + 1;
  l.py = static_cast<int>(std::ceil(k_max * g.dy() / (2.0 * pi))) + 1;
  return l;
}

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
