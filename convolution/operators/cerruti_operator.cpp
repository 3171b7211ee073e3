#include "convolution/operators/cerruti_operator.hpp"

#include <utility>
#include <vector>

#include "convolution/kernels/periodic_traction_kernels.hpp"

namespace coatfft {

CerrutiOperator::CerrutiOperator(const Grid& grid, const Material& material, Planning planning)
    : CerrutiOperator(grid, LayerStack(material), TractionKernelOptions{}, planning) {}

CerrutiOperator::CerrutiOperator(const Grid& grid, const LayerStack& stack,
                                 const TractionKernelOptions& options, Planning planning,
                                 TractionKernelReport* report)
    : convolution_(grid, 3, planning) {
  add_outputs(traction_kernels(grid, stack, options, report));
}

CerrutiOperator::CerrutiOperator(const Grid& grid, const LayerStack& stack,
                                 const PeriodicKernelOptions& options, Planning planning)
    : convolution_(grid, 3, planning, true) {
  add_outputs(periodic_traction_kernels(grid, stack, options));
}

void CerrutiOperator::add_outputs(const TractionKernels& c) {
  // By reciprocity (Betti), u_x at A under a pressure on the cell at B is u_z at B under a unit
  // q_x at A: K_xp(d) = K_zx(-d) = -zx(d), since zx is odd in x; likewise K_yp = -zy. The
  // same holds for any elastic body, layered ones included.
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

void CerrutiOperator::apply_in_plane(const Field* pressure, const Field* qx, const Field* qy,
                                     std::array<Field, 3>& u) {
  const Field* loads[3] = {pressure, qx, qy};
  convolution_.apply(loads, fields_, 2);  // the outputs u_x, u_y (add_outputs' order)
  for (int d = 0; d < 2; ++d) std::swap(u[d], fields_[d]);
}

}  // namespace coatfft
