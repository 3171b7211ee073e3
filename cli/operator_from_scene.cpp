#include "cli/operator_from_scene.hpp"

#include <chrono>

#include "convolution/dcfft_operator.hpp"
#include "convolution/direct_operator.hpp"
#include "convolution/fftw_plan.hpp"
#include "convolution/influence_kernel.hpp"
#include "core/error.hpp"

namespace coatfft::cli {

BuiltOperator operator_from_scene(const Scene& scene) {
  const MethodSpec& method = scene.method;
  const Planning planning = method.planning == "measure" ? Planning::measure : Planning::estimate;
  if (!method.wisdom.empty()) load_fftw_wisdom(method.wisdom.string());

  BuiltOperator built;
  const auto start = std::chrono::steady_clock::now();
  if (method.name == "dcfft" || method.name == "direct") {
    // Love's coefficients exist in closed form only for the homogeneous half-space.
    COATFFT_REQUIRE(scene.body.is_homogeneous(), "[method] name = \"", method.name,
                    "\" uses Love's coefficients of a homogeneous half-space; for a coated body "
                    "use \"frf-split\", \"frf-dcfft\" or \"frf-spectral\"");
    const InfluenceKernel kernel =
        love_kernel(scene.grid, scene.body.substrate().plane_strain_modulus());
    if (method.name == "dcfft")
      built.op = std::make_unique<DcfftOperator>(kernel, planning, method.threads);
    else
      built.op = std::make_unique<DirectOperator>(kernel);
  } else {
    throw InvalidArgument(detail::concat("[method] name = \"", method.name, "\" is not built in"));
  }
  built.setup_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!method.wisdom.empty()) save_fftw_wisdom(method.wisdom.string());
  return built;
}

}  // namespace coatfft::cli
