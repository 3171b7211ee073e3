#pragma once
// The surface displacements u_x, u_y, u_z of a body under a pressure and the tangential tractions
// q_x, q_y (Cerruti's problem): the 3 x 3 surface response in space, by DC-FFT (Liu, Wang & Liu
// 2000) of the cell coefficients of convolution/kernels/traction_kernels.hpp -- for a homogeneous
// half-space Love's (1929) coefficient of a uniformly pressed cell and Cerruti's (1882) of a
// uniformly sheared one (docs/theory.md 1.3b), exact (to rounding) for cell-wise constant loads;
// for a bonded layer stack the split of docs/theory.md 2.9. The in-plane displacements under
// pressure follow by reciprocity.
#include <array>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "../../layers/layer_stack.hpp"
#include "../../materials/material.hpp"
#include "../fft/parity_convolution.hpp"
#include "../kernels/periodic_kernel.hpp"
#include "../kernels/traction_kernels.hpp"

namespace coatfft {

class CerrutiOperator {
 public:
  /// Plans the nine kernels of `material` on `grid` (the coefficients in closed form).
  CerrutiOperator(const Grid& grid, const Material& material,
                  Planning planning = Planning::estimate);
  /// Plans the nine kernels of any bonded `stack` (traction_kernels: its errors, InvalidArgument
  /// for a frictionless interface among them); `report`, when given, receives their diagnostics.
  CerrutiOperator(const Grid& grid, const LayerStack& stack, const TractionKernelOptions& options,
                  Planning planning = Planning::estimate, TractionKernelReport* report = nullptr);
  /// Plans the nine periodic kernels of any bonded `stack` on the periodic surface `grid`
  /// (periodic_traction_kernels: its errors): circular convolutions over the period, every
  /// displacement with zero mean.
  CerrutiOperator(const Grid& grid, const LayerStack& stack, const PeriodicKernelOptions& options,
                  Planning planning = Planning::estimate);

  const Grid& grid() const { return convolution_.grid(); }
  bool periodic() const { return convolution_.periodic(); }

  /// u = (u_x, u_y, u_z) [m] (each (nx, ny); u_z into the body) under the pressure (compression
  /// positive) and the tractions q_x, q_y the surface receives (null: zero), each (nx, ny) [Pa]
  /// as cell values. Throws InvalidArgument for a shape that is not the grid's or a value that is
  /// not finite.
  void apply(const Field& pressure, const Field* qx, const Field* qy, std::array<Field, 3>& u);
  /// u_x and u_y alone (u[2] is left as it was), under `pressure` (null: zero) and the tractions:
  /// one transform of each given load and two inverse ones, against apply's three and three.
  void apply_in_plane(const Field* pressure, const Field* qx, const Field* qy,
                      std::array<Field, 3>& u);

  /// Bytes held: the kernels' spectra and the transform buffers.
  std::size_t memory_bytes() const { return convolution_.memory_bytes(); }

 private:
  ParityConvolution convolution_;  // outputs u_x, u_y, u_z; loads p, q_x, q_y
  std::vector<Field> fields_;

  void add_outputs(const TractionKernels& c);
};

}  // namespace coatfft
