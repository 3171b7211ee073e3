#include "validation/axisymmetric_traction.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "frf/traction_response.hpp"

namespace coatfft {

namespace {

double member(const TractionFrfs& f, double TractionFrfs::*m) {
  return f.*m;
}

// Smallest power-of-two multiple of 1e-3/a from which k f(k) equals its limit at infinity to
// `threshold` (relative to the largest limit) for every one of the four FRFs over 8 doublings:
// the layered terms decay like exp(-2 k h_top) (docs/theory.md 2.2).
double converged_wavenumber(const TractionResponse& response, double a, double threshold) {
  const TractionFrfs& inf = response.at_infinity();
  const double size =
      std::max({std::abs(inf.zz), std::abs(inf.s), std::abs(inf.d), std::abs(inf.c)});
  int run = 0;
  double start = 0.0;
  double k = 1e-3 / a;
  for (int j = 0; j < 400; ++j, k *= 2.0) {
    const TractionFrfs f = response(k);
    double worst = 0.0;
    for (auto m : {&TractionFrfs::zz, &TractionFrfs::s, &TractionFrfs::d, &TractionFrfs::c})
      worst = std::max(worst, std::abs(k * member(f, m) - member(inf, m)));
    if (worst <= threshold * size) {
      if (run == 0) start = k;
      if (++run == 8) return start;
    } else {
      run = 0;
    }
  }
  throw Error("axisymmetric_surface_displacement: the surface FRFs do not approach their limits");
}

}  // namespace

SurfaceDisplacement axisymmetric_surface_displacement(const LayerStack& stack,
                                                      AxisymmetricLoad load,
                                                      LoadDirection direction, double amplitude,
                                                      double a, double x, double y,
                                                      double rel_tol) {
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "axisymmetric_surface_displacement: a = ", a,
                  " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y) && std::isfinite(amplitude),
                  "axisymmetric_surface_displacement: the point and the amplitude must be finite");
  COATFFT_REQUIRE(rel_tol >= 1e-12 && rel_tol < 1e-2,
                  "axisymmetric_surface_displacement: rel_tol = ", rel_tol,
                  ", but it must lie in [1e-12, 1e-2)");
  const TractionResponse response(stack);
  COATFFT_REQUIRE(response.bonded(),
                  "axisymmetric_surface_displacement: every interface must be "
                  "bonded (docs/theory.md 2.9)");
  const double r = std::hypot(x, y);
  COATFFT_REQUIRE(r == 0.0 || r >= 1e-3 * a, "axisymmetric_surface_displacement: r = ", r,
                  " m is closer than 1e-3 a to the centre (the quadrature's range grows like a/r)");
  const double k_converged = converged_wavenumber(response, a, 1e-3 * rel_tol);
  const TractionFrfs& inf = response.at_infinity();
  const TractionFrfs& zero = response.at_zero();
  const double scale = std::max(std::abs(zero.s), std::abs(inf.s)) / a;
  const auto integral = [&](double TractionFrfs::*m, int order) {
    return hankel_load_integral([&](double k) { return k * member(response(k), m); },
                                member(inf, m), k_converged, order, load, amplitude, a, r, scale,
                                rel_tol);
  };
  const double cos_phi = r > 0 ? x / r : 1.0, sin_phi = r > 0 ? y / r : 0.0;
  const double cos_2phi = cos_phi * cos_phi - sin_phi * sin_phi, sin_2phi = 2 * cos_phi * sin_phi;
  SurfaceDisplacement u;
  if (direction == LoadDirection::pressure) {
    const double coupling = r > 0 ? integral(&TractionFrfs::c, 1) : 0.0;
    u.ux = -cos_phi * coupling;
    u.uy = -sin_phi * coupling;
    u.uz = integral(&TractionFrfs::zz, 0);
  } else {
    const double deviatoric = r > 0 ? integral(&TractionFrfs::d, 2) : 0.0;
    u.ux = integral(&TractionFrfs::s, 0) - cos_2phi * deviatoric;
    u.uy = -sin_2phi * deviatoric;
    u.uz = r > 0 ? cos_phi * integral(&TractionFrfs::c, 1) : 0.0;
  }
  return u;
}

}  // namespace coatfft
