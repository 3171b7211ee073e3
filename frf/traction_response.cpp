#include "frf/traction_response.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace coatfft {

namespace {

TractionFrfs from_modes(const ModeFields& m) {
  return {m.uz_p, 0.5 * (m.uL_q + m.uT_t), 0.5 * (m.uL_q - m.uT_t), m.uz_q};
}

// S(k) of a stack as an Frf, for split_frf_kernel.
class InPlaneFrf final : public Frf {
 public:
  explicit InPlaneFrf(const LayerStack& stack) : response_(stack) {}
  double operator()(double k) const override { return response_(k).s; }
  double c0() const override { return response_.at_zero().s; }
  double c_inf() const override { return response_.at_infinity().s; }
  std::string name() const override { return "in_plane"; }

 private:
  TractionResponse response_;
};

}  // namespace

TractionFrfs half_space_traction_frfs(const Material& material) {
  const double mu = material.shear_modulus();
  const double nu = material.poisson_ratio();
  return {(1.0 - nu) / mu, (2.0 - nu) / (2.0 * mu), -nu / (2.0 * mu),
          (1.0 - 2.0 * nu) / (2.0 * mu)};
}

TractionResponse::TractionResponse(const LayerStack& stack)
    : modes_(stack),
      at_zero_(half_space_traction_frfs(stack.substrate())),
      at_infinity_(half_space_traction_frfs(
          stack.is_homogeneous() ? stack.substrate() : stack.coatings().front().material)),
      bonded_(stack.all_bonded()) {}

TractionFrfs TractionResponse::operator()(double k) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "surface response: k = ", k,
                  " rad/m, but it must be finite and > 0");
  const double surface[1] = {0.0};
  return from_modes(modes_.at(k, surface).front());
}

std::unique_ptr<Frf> in_plane_frf(const LayerStack& stack) {
  COATFFT_REQUIRE(stack.all_bonded(),
                  "in-plane FRF: a stack with a frictionless interface has no finite in-plane "
                  "compliance as k -> 0 (the coating above it slides)");
  return std::make_unique<InPlaneFrf>(stack);
}

}  // namespace coatfft
