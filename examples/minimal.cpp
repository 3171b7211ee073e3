// The library in a few lines: displacement of a Hertz pressure on a TiN-coated steel
// half-space, with the split FRF kernel and the DC-FFT operator. Prints the centre value next to
// the continuous Hankel-transform reference.
#include <cmath>
#include <cstdio>

#include "convolution/dcfft_operator.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/catalog.hpp"
#include "validation/hankel_displacement.hpp"

int main() {
  using namespace coatfft;
  const Grid grid(97, 97, 4e-3, 4e-3);  // cells, metres
  const LayerStack body({Coating{material_by_name("titanium_nitride"), 50e-6, Interface::bonded}},
                        material_by_name("steel"));
  const auto frf = make_frf(body);
  DcfftOperator op(split_frf_kernel(grid, *frf));  // plan once ...
  const Field p = hertz_pressure(grid, 1e9, 1e-3, Sampling::cell_average);
  const Field u = op.apply(p);  // ... apply many times
  const double u_ref = hankel_displacement(*frf, AxisymmetricLoad::hertz, 1e9, 1e-3, 0.0);
  std::printf("u(0) = %.6e m (Hankel reference %.6e m, difference %.1e of u(0))\n", u(48, 48),
              u_ref, (u(48, 48) - u_ref) / u_ref);
  return std::abs(u(48, 48) - u_ref) < 1e-3 * u_ref ? 0 : 1;
}
