// The library in a few lines: displacement of a Hertz pressure on a TiN-coated steel
// half-space, by the split FRF kernel and DC-FFT (method frf-split). Prints the centre value next
// to the continuous Hankel-transform reference. Uses only the installed public headers, so it
// builds the same in this tree, against an install (find_package) and through add_subdirectory.
#include <cmath>
#include <coatfft/coatfft.hpp>
#include <cstdio>

int main() {
  using namespace coatfft;
  const Grid grid(97, 97, 4e-3, 4e-3);  // cells, metres
  const LayerStack body({Coating{material_by_name("titanium_nitride"), 50e-6, Interface::bonded}},
                        material_by_name("steel"));
  OperatorOptions options;
  options.method = Method::frf_split;
  const BuiltOperator built = make_operator(grid, body, options);  // plan once ...
  const Field p = hertz_pressure(grid, 1e9, 1e-3, Sampling::cell_average);
  const Field u = built.op->apply(p);  // ... apply many times
  const double u_ref =
      hankel_displacement(*make_frf(body), AxisymmetricLoad::hertz, 1e9, 1e-3, 0.0);
  std::printf("%s: u(0) = %.6e m (Hankel reference %.6e m, difference %.1e of u(0))\n",
              built.op->name().c_str(), u(48, 48), u_ref, (u(48, 48) - u_ref) / u_ref);
  return std::abs(u(48, 48) - u_ref) < 1e-3 * u_ref ? 0 : 1;
}
