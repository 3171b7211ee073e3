#pragma once
// The surface displacements u_x, u_y, u_z of a homogeneous half-space under a pressure and the
// tangential tractions q_x, q_y: the 3 x 3 surface response in space, by DC-FFT (Liu, Wang & Liu
// 2000) of Love's (1929) coefficient of a uniformly pressed cell and Cerruti's (1882) of a
// uniformly sheared one (docs/theory.md 1.3b), the in-plane displacements under pressure by
// reciprocity. Exact (to rounding) for cell-wise constant loads.
#include <array>

#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "../materials/material.hpp"
#include "parity_convolution.hpp"

namespace coatfft {

class CerrutiOperator {
 public:
  /// Plans the nine kernels of `material` on `grid` (the coefficients in closed form).
  CerrutiOperator(const Grid& grid, const Material& material,
                  Planning planning = Planning::estimate);

  const Grid& grid() const { return convolution_.grid(); }

  /// u = (u_x, u_y, u_z) [m] (each (nx, ny); u_z into the body) under the pressure (compression
  /// positive) and the tractions q_x, q_y the surface receives (null: zero), each (nx, ny) [Pa]
  /// as cell values. Throws InvalidArgument for a shape that is not the grid's or a value that is
  /// not finite.
  void apply(const Field& pressure, const Field* qx, const Field* qy, std::array<Field, 3>& u);

 private:
  ParityConvolution convolution_;  // outputs u_x, u_y, u_z; loads p, q_x, q_y
  std::vector<Field> fields_;
};

}  // namespace coatfft
