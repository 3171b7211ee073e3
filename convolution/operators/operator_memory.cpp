#include "convolution/operators/operator_memory.hpp"

#include <cmath>

#include "convolution/operators/detail/dcfft_operator.hpp"
#include "core/detail/fft_size.hpp"

namespace coatfft {

namespace {

// The transform lattice of make_operator's methods.
OperatorMemory transform_lattice(const Grid& grid, const OperatorOptions& o) {
  switch (o.method) {
    case Method::direct:
      return {};
    case Method::frf_spectral:
      return {0.0, static_cast<std::ptrdiff_t>(std::llround(o.alpha * double(grid.nx()))),
              static_cast<std::ptrdiff_t>(std::llround(o.alpha * double(grid.ny())))};
    default: {
      // DC-FFT's padded lattice: frf-dcfft at alpha = 2 hands it a spectrum (exactly 2n).
      const auto form = o.method == Method::frf_dcfft && o.alpha == 2.0
                            ? InfluenceKernel::Form::spectrum
                            : InfluenceKernel::Form::coefficients;
      return {0.0, DcfftOperator::padded_size(grid.nx(), form),
              DcfftOperator::padded_size(grid.ny(), form)};
    }
  }
}

}  // namespace

OperatorMemory estimated_memory(const Grid& grid, const OperatorOptions& options) {
  if (options.boundary == Boundary::periodic) {
    // The grid is the lattice (no padding): the half spectrum the transforms run through and the
    // kernel's multiplier on a quarter of the modes (convolution/fft/detail/spectral_filter.hpp).
    const double hx = double(grid.nx() / 2 + 1);
    const double spectrum = 16.0 * hx * double(grid.ny());
    return {spectrum + 8.0 * hx * double(grid.ny() / 2 + 1), grid.nx(), grid.ny()};
  }
  OperatorMemory m = transform_lattice(grid, options);
  const double lattice = double(m.lattice_nx) * double(m.lattice_ny);
  const bool builds_on_lattice =
      options.method == Method::frf_split || options.method == Method::frf_dcfft;
  m.bytes = (2.5 * 8.0 + (builds_on_lattice ? 8.0 : 0.0)) * lattice;
  if (options.method == Method::frf_dcfft)  // the FRF sampled on the alpha-extended lattice
    m.bytes += 16.0 * options.alpha * options.alpha * double(grid.nx()) * double(grid.ny());
  return m;
}

double estimated_cerruti_bytes(const Grid& grid) {
  const double hx = double(detail::fast_even_fft_size(2 * grid.nx() - 1)) / 2 + 1;
  const double my = double(detail::fast_even_fft_size(2 * grid.ny() - 1));
  const double cells = double(grid.nx()) * double(grid.ny());
  return 8.0 * (9 * hx * (my / 2 + 1) + 3 * 2 * hx * my + 9 * cells +
                4 * (grid.nx() + 1.0) * (grid.ny() + 1.0) + 4 * std::pow(34.0 * 16, 2));
}

}  // namespace coatfft
