#include "bench/timed_setup.hpp"

#include <chrono>
#include <memory>
#include <numbers>

#include "convolution/frf_influence_kernel.hpp"
#include "convolution/g0.hpp"
#include "convolution/influence_kernel.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"

namespace coatfft::bench {

TimedSetup timed_setup(const Grid& grid, const LayerStack& body, const OperatorOptions& options) {
  using detail::seconds_since;
  check_operator_options(grid, options);
  TimedSetup s;
  const auto start = std::chrono::steady_clock::now();
  switch (options.method) {
    case Method::frf_spectral:
    case Method::frf_split: {
      s.built = make_operator(grid, body, options);
      const OperatorReport& r = s.built.report;
      s.g0_s = r.g0 ? r.g0->seconds : 0.0;
      s.kernel_s = r.split ? r.split->seconds : 0.0;
      s.transform_s = r.setup_seconds - s.g0_s - s.kernel_s;
      break;
    }
    case Method::direct:
    case Method::dcfft: {
      COATFFT_REQUIRE(body.is_homogeneous(), "method \"", to_string(options.method),
                      "\" uses Love's coefficients of a homogeneous half-space");
      auto t = std::chrono::steady_clock::now();
      const InfluenceKernel kernel =
          love_kernel(grid, body.substrate().plane_strain_modulus(), options.threads);
      s.kernel_s = seconds_since(t);
      s.built = make_operator(kernel, options);
      s.transform_s = s.built.report.setup_seconds;
      break;
    }
    case Method::frf_dcfft: {
      // g(0) on the alpha-extended lattice, then the kernel (at alpha = 2 its spectrum: the FRF
      // samples; otherwise coefficients), then DC-FFT's plans and kernel transform.
      const std::unique_ptr<Frf> frf = make_frf(body);
      using std::numbers::pi;
      const G0Result g0 =
          compute_g0(*frf, 2.0 * pi / (options.alpha * grid.lx()),
                     2.0 * pi / (options.alpha * grid.ly()), options.g0, options.g0_tolerance);
      s.g0_s = g0.seconds;
      auto t = std::chrono::steady_clock::now();
      const InfluenceKernel kernel =
          frf_dcfft_kernel(grid, *frf, options.alpha, g0, options.threads);
      s.kernel_s = seconds_since(t);
      s.built = make_operator(kernel, options);
      s.transform_s = s.built.report.setup_seconds;
      break;
    }
  }
  s.setup_s = seconds_since(start);
  return s;
}

}  // namespace coatfft::bench
