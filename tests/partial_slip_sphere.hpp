#pragma once
// The partial-slip tests' contact: a rigid sphere (R = 10 mm, 20 N, mu = 0.3) on a nearly
// incompressible half-space (nu = 0.4999: the coupling beta = (1 - 2 nu)/(2 (1 - nu)) is 2e-4, the
// references' uncoupled case), on a grid 4a + 1 cells wide with `cells` cells per contact radius.
#include <cmath>
#include <memory>

#include "contact/indenter.hpp"
#include "contact/partial_slip.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/operators/cerruti_operator.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "validation/cattaneo_mindlin.hpp"

namespace coatfft_test {

inline constexpr double kBallRadius = 0.01, kPressLoad = 20.0, kFriction = 0.3;
inline const coatfft::Material kIncompressible(2e9, coatfft::Material::max_poisson_ratio);

struct SphereOnHalfSpace {
  coatfft::CattaneoMindlin cm;
  coatfft::Grid grid;
  coatfft::DcfftOperator op;
  coatfft::ContactSolver solver;
  coatfft::RelativeSurfaceResponse response;
  coatfft::Field h;
  SphereOnHalfSpace(const coatfft::Material& m, int cells)
      : cm(coatfft::cattaneo_mindlin(kPressLoad, kBallRadius, m, kFriction)),
        grid(4 * cells + 1, 4 * cells + 1, (4 * cells + 1) * cm.hertz.contact_radius / cells,
             (4 * cells + 1) * cm.hertz.contact_radius / cells),
        op(coatfft::love_kernel(grid, m.plane_strain_modulus())),
        solver(op),
        response(std::make_shared<coatfft::CerrutiOperator>(grid, m)),
        h(coatfft::height(grid, coatfft::Sphere{kBallRadius})) {}

  /// The normal contact at rest, without tractions.
  coatfft::PartialSlipState rest() {
    return rest_state(response, solver.solve(h, coatfft::ContactControl::load, kPressLoad));
  }
  /// One step from `from` under the tangential `control` = `target`.
  coatfft::PartialSlipResult step(coatfft::TangentialControl control, double target,
                                  const coatfft::PartialSlipState& from) {
    coatfft::PartialSlipOptions o;
    o.friction = kFriction;
    return solve_partial_slip(solver, response, h, coatfft::ContactControl::load, kPressLoad,
                              control, target, o, from);
  }
  /// The root-mean-square error of q_x against Cattaneo's traction over the contact, over mu p0.
  double traction_error(const coatfft::PartialSlipResult& r, double q_load) const {
    return coatfft::rms_traction_error(grid, r.qx, cm, q_load);
  }
};

}  // namespace coatfft_test
