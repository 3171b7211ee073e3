#pragma once
// Brute-force discrete convolution: the O((nx ny)^2) reference every fast operator is tested
// against. Use on small grids only (64 x 64 takes about 20 ms).
#include <string>

#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/surface_operator.hpp"

namespace coatfft {

/// u_ij = sum_kl K(i - k, j - l) p_kl by direct multi-summation over the kernel's grid.
class DirectOperator final : public SurfaceOperator {
 public:
  /// Keeps the kernel's wrap-around array (coefficient form; throws InvalidArgument for the
  /// spectrum form).
  explicit DirectOperator(const InfluenceKernel& kernel);

  const Grid& grid() const override { return grid_; }
  /// Throws InvalidArgument unless `pressure` has shape (nx, ny).
  void apply(const Field& pressure, Field& displacement) override;
  Method method() const override { return Method::direct; }
  using SurfaceOperator::apply;

 private:
  Grid grid_;
  Field wrapped_;  // (2nx, 2ny) wrap-around coefficients
};

}  // namespace coatfft
