#include "bench/timed_setup.hpp"

namespace coatfft::bench {

TimedSetup timed_setup(const Grid& grid, const LayerStack& body, const OperatorOptions& options) {
  TimedSetup s;
  s.built = make_operator(grid, body, options);
  const OperatorReport& r = s.built.report;
  s.kernel_s = r.kernel_seconds;
  s.g0_s = r.g0 ? r.g0->seconds : 0.0;
  s.setup_s = r.setup_seconds;
  s.transform_s = s.setup_s - s.kernel_s - s.g0_s;
  return s;
}

}  // namespace coatfft::bench
