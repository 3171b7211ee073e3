#include "cli/operator_from_scene.hpp"

#include <chrono>

#include "convolution/dcfft_operator.hpp"
#include "convolution/direct_operator.hpp"
#include "convolution/fftw_plan.hpp"
#include "convolution/frf_dcfft_operator.hpp"
#include "convolution/frf_spectral_operator.hpp"
#include "convolution/g0.hpp"
#include "convolution/influence_kernel.hpp"
#include "convolution/split_frf_kernel.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"

namespace coatfft::cli {

namespace {

// An omitted g(0) is no value at all (the operator uses 0 in its place): reported as null.
nlohmann::json g0_report(const G0Result& g0) {
  const bool omitted = g0.method == G0Method::omitted;
  return {{"g0", omitted ? nlohmann::json() : nlohmann::json(g0.value)},
          {"g0_method", std::string(to_string(g0.method))},
          {"g0_seconds", g0.seconds},
          {"g0_estimated_error", omitted ? nlohmann::json() : nlohmann::json(g0.estimated_error)}};
}

// g(0) only shifts every displacement by one constant, which a load-controlled contact absorbs
// in its approach; when that approach is not reported, g(0) is not computed at all.
G0Method g0_method_for(const Scene& scene) {
  if (scene.contact && !scene.contact->report_approach) return G0Method::omitted;
  return scene.method.g0 == "quadrature" ? G0Method::quadrature : G0Method::regularized;
}

}  // namespace

BuiltOperator operator_from_scene(const Scene& scene) {
  const MethodSpec& method = scene.method;
  const Planning planning = method.planning == "measure" ? Planning::measure : Planning::estimate;
  const G0Method g0_method = g0_method_for(scene);
  if (!method.wisdom.empty()) load_fftw_wisdom(method.wisdom.string());

  BuiltOperator built;
  const auto start = std::chrono::steady_clock::now();
  if (method.name == "dcfft" || method.name == "direct") {
    // Love's coefficients exist in closed form only for the homogeneous half-space.
    COATFFT_REQUIRE(scene.body.is_homogeneous(), "[method] name = \"", method.name,
                    "\" uses Love's coefficients of a homogeneous half-space; for a coated body "
                    "use \"frf-split\", \"frf-dcfft\" or \"frf-spectral\"");
    // DC-FFT needs only the kernel's quarter (love_kernel_quarter: no (2nx, 2ny) array).
    const EvenInfluenceKernel quarter = love_kernel_quarter(
        scene.grid, scene.body.substrate().plane_strain_modulus(), method.threads);
    if (method.name == "dcfft")
      built.op = std::make_unique<DcfftOperator>(quarter, planning, method.threads);
    else
      built.op = std::make_unique<DirectOperator>(wrap_even_kernel(quarter));
  } else {
    const auto frf = make_frf(scene.body);
    built.report["frf"] = frf->name();
    if (method.name == "frf-spectral") {
      auto op = std::make_unique<FrfSpectralOperator>(scene.grid, *frf, method.alpha, g0_method,
                                                      method.g0_tol, planning, method.threads);
      built.report.update(g0_report(op->g0()));
      built.report["alpha"] = method.alpha;
      built.op = std::move(op);
    } else if (method.name == "frf-dcfft") {
      G0Result g0{};
      built.op = frf_dcfft_operator(scene.grid, *frf, method.alpha, g0_method, method.g0_tol, &g0,
                                    planning, method.threads);
      built.report.update(g0_report(g0));
      built.report["alpha"] = method.alpha;
    } else {
      // The split kernel needs no g(0): the singular part of H is taken in closed form in space.
      SplitKernelReport report;
      SplitKernelOptions options;
      options.threads = method.threads;
      const EvenInfluenceKernel kernel =
          split_frf_kernel_quarter(scene.grid, *frf, options, &report);
      built.report["split_beta"] = report.beta;
      built.report["split_seconds"] = report.seconds;
      built.op = std::make_unique<DcfftOperator>(kernel, planning, method.threads);
    }
  }
  built.setup_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!method.wisdom.empty()) save_fftw_wisdom(method.wisdom.string());
  return built;
}

}  // namespace coatfft::cli
