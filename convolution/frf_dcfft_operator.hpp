#pragma once
// The seed paper's second algorithm (Spinu 2021, section 4; theory.md 4.4) as one operator: FRF
// -> influence coefficients on the alpha-extended lattice -> DC-FFT. At alpha = 2 the extended
// lattice is DC-FFT's own padded (2nx, 2ny) lattice, so the sampled spectrum H sinc sinc *is*
// the spectrum DcfftOperator would get back from the coefficients: the inverse transform, the
// (2nx, 2ny) coefficient array and the forward transform are skipped (the round trip only drops
// the offsets +-nx, +-ny, which never reach the cropped output). Same result to rounding, about
// a third less setup at 1024^2 (docs/benchmarks_setup.md).
#include <memory>

#include "convolution/dcfft_operator.hpp"
#include "convolution/g0.hpp"
#include "frf/frf.hpp"

namespace coatfft {

/// DcfftOperator(frf_influence_kernel(grid, frf, alpha, g0, threads), planning, threads), by the
/// spectrum route above when alpha nx = 2 nx and alpha ny = 2 ny; the same arguments and errors
/// as frf_influence_kernel.
std::unique_ptr<DcfftOperator> frf_dcfft_operator(const Grid& grid, const Frf& frf, double alpha,
                                                  const G0Result& g0,
                                                  Planning planning = Planning::estimate,
                                                  int threads = 1);

/// As above with g(0) computed by `g0_method` to `g0_tolerance` on the extended lattice (as
/// frf_influence_kernel does); `g0_used`, if given, receives it.
std::unique_ptr<DcfftOperator> frf_dcfft_operator(const Grid& grid, const Frf& frf, double alpha,
                                                  G0Method g0_method, double g0_tolerance,
                                                  G0Result* g0_used = nullptr,
                                                  Planning planning = Planning::estimate,
                                                  int threads = 1);

}  // namespace coatfft
