#include "scene/contact_options.hpp"

#include <cstddef>

#include "core/error.hpp"

namespace coatfft::scene {

ContactOptions solver_options(const ContactSpec& spec, int threads, ProgressObserver& progress) {
  ContactOptions options;
  options.threads = threads;
  options.tolerance = spec.tolerance;
  options.max_iterations = spec.max_iterations;
  // Under load control the approach is the only output that depends on g(0) (docs/contact.md).
  options.compute_approach = spec.report_approach;
  options.hardness = spec.hardness;
  options.on_iteration = [&progress](int k, double residual) { progress.iteration(k, residual); };
  options.on_value = [&progress, load = spec.load.has_value()](std::size_t k, std::size_t n,
                                                               double value) {
    progress.step(detail::concat(load ? "load " : "approach ", k + 1, " of ", n, ": ", value,
                                 load ? " N" : " m"));
  };
  return options;
}

}  // namespace coatfft::scene
