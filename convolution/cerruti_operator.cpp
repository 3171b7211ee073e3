#include "convolution/cerruti_operator.hpp"

#include <utility>
#include <vector>

#include "convolution/cerruti_influence.hpp"
#include "convolution/love_influence.hpp"

namespace coatfft {

namespace {

// The coefficients of the quarter 0 <= i < nx, 0 <= j < ny: Love's u_z under p, and Cerruti's
// (xx, yx, zx) under q_x and, with the axes swapped, under q_y (convolution/cerruti_influence.hpp).
struct Coefficients {
  Field zp, xx, yx, zx, yy, zy;
};

Coefficients coefficients(const Grid& g, const Material& m) {
  const std::ptrdiff_t nx = g.nx(), ny = g.ny();
  const double dx = g.dx(), dy = g.dy();
  Coefficients c{Field(nx, ny), Field(nx, ny), Field(nx, ny),
                 Field(nx, ny), Field(nx, ny), Field(nx, ny)};
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      const double x = i * dx, y = j * dy;
      c.zp(i, j) = love_influence(x, y, dx, dy) / m.plane_strain_modulus();
      const CerrutiCoefficients q = cerruti_influence(x, y, dx, dy, m);
      c.xx(i, j) = q.xx;
      c.yx(i, j) = q.yx;
      c.zx(i, j) = q.zx;
      const CerrutiCoefficients swapped = cerruti_influence(y, x, dy, dx, m);
      c.yy(i, j) = swapped.xx;
      c.zy(i, j) = swapped.zx;
    }
  return c;
}

}  // namespace

CerrutiOperator::CerrutiOperator(const Grid& grid, const Material& material, Planning planning)
    : convolution_(grid, 3, planning) {
  const Coefficients c = coefficients(grid, material);
  // By reciprocity (Betti), u_x at A under a pressure on the cell at B is u_z at B under a unit
  // q_x at A: K_xp(d) = K_zx(-d) = -zx(d), since zx is odd in x; likewise K_yp = -zy.
  convolution_.add_output(
      std::vector<ParityKernel>{{-c.zx, true, false}, {c.xx, false, false}, {c.yx, true, true}});
  convolution_.add_output(
      std::vector<ParityKernel>{{-c.zy, false, true}, {c.yx, true, true}, {c.yy, false, false}});
  convolution_.add_output(
      std::vector<ParityKernel>{{c.zp, false, false}, {c.zx, true, false}, {c.zy, false, true}});
}

void CerrutiOperator::apply(const Field& pressure, const Field* qx, const Field* qy,
                            std::array<Field, 3>& u) {
  const Field* loads[3] = {&pressure, qx, qy};
  convolution_.apply(loads, fields_);
  for (int d = 0; d < 3; ++d) std::swap(u[d], fields_[d]);
}

}  // namespace coatfft
