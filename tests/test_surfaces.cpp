// Self-affine random surfaces (surfaces/self_affine_surface.hpp): the power spectrum mode by mode
// against the requested C(q) (an independent forward FFT of the result), the rms height and slope
// exactly as asked, the spectral slope against the closed form of a cosine, reproducibility by
// seed, and the refusals.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "core/error.hpp"
#include "surfaces/self_affine_surface.hpp"

using namespace coatfft;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

struct Mode {
  double q, power;  // |k| [rad/m] and |h_k|^2 (h_k the FFT over the cell count) [m^2]
};

// Every mode of the half spectrum (x the halved axis) of h by FFTW's r2c.
std::vector<Mode> modes(const Grid& g, const Field& h) {
  FftwRealBuffer in(static_cast<std::size_t>(h.size()));
  std::copy(h.data(), h.data() + h.size(), in.data());
  const std::ptrdiff_t hx = g.nx() / 2 + 1;
  FftwComplexBuffer out(static_cast<std::size_t>(hx * g.ny()));
  const FftwPlan plan = FftwPlan::create(1, [&] {
    return fftw_plan_dft_r2c_2d(int(g.ny()), int(g.nx()), in.data(), out.data(), FFTW_ESTIMATE);
  });
  plan.execute();
  std::vector<Mode> m;
  const double cells = static_cast<double>(h.size());
  for (std::ptrdiff_t j = 0; j < g.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < hx; ++i) {
      const double sj = j <= g.ny() / 2 ? double(j) : double(j - g.ny());
      const double q = std::hypot(two_pi * i / g.lx(), two_pi * sj / g.ly());
      m.push_back({q, std::norm(as_complex(out.data())[j * hx + i]) / (cells * cells)});
    }
  return m;
}

}  // namespace

TEST_CASE("a self-affine surface has the requested spectrum mode by mode", "[surfaces]") {
  const Grid g(128, 96, 1e-3, 0.75e-3);
  SelfAffineSpec spec;
  spec.hurst = 0.7;
  spec.rms_height = 0.5e-6;
  spec.short_cutoff = 8 * g.dx();
  spec.long_cutoff = 0.25e-3;
  spec.seed = 42;
  const Field h = self_affine_surface(g, spec);
  REQUIRE(h.rows() == 128);
  REQUIRE(h.cols() == 96);
  CHECK(std::sqrt(h.square().mean()) == Approx(0.5e-6).epsilon(1e-13));
  CHECK(std::abs(h.mean()) < 1e-15 * 0.5e-6);
  const double q_s = two_pi / *spec.short_cutoff, q_r = two_pi / *spec.long_cutoff;
  // C(q) / C0 = (q/q_r)^(-2(1 + H)) between the cut-offs, 1 below q_r, 0 above q_s: the ratio of
  // each mode's power to it is one constant C0.
  double c0 = 0.0, spread = 0.0, above = 0.0, peak = 0.0;
  std::vector<double> ratios;
  for (const Mode& m : modes(g, h)) {
    peak = std::max(peak, m.power);
    if (m.q == 0.0) {
      CHECK(m.power < 1e-30 * 0.25e-12);
    } else if (m.q > q_s * (1 + 1e-12)) {
      above = std::max(above, m.power);
    } else {
      ratios.push_back(m.power / std::pow(std::max(m.q, q_r) / q_r, -2.0 * (1.0 + spec.hurst)));
    }
  }
  c0 = ratios.front();
  for (double r : ratios) spread = std::max(spread, std::abs(r / c0 - 1.0));
  CHECK(ratios.size() > 300);
  CHECK(spread < 1e-10);
  CHECK(above < 1e-28 * peak);
}

TEST_CASE("a self-affine surface matches a requested rms slope", "[surfaces]") {
  const Grid g(64, 64, 1e-3, 1e-3);
  SelfAffineSpec spec;
  spec.hurst = 0.5;
  spec.rms_slope = 0.1;
  const Field h = self_affine_surface(g, spec);
  CHECK(spectral_rms_slope(g, h) == Approx(0.1).epsilon(1e-13));
  // The spectral slope of A cos(2 pi m x / L): A (2 pi m / L)/sqrt(2).
  Field c(64, 64);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) c(i, j) = 2e-6 * std::cos(two_pi * 5 * g.x(i) / g.lx());
  CHECK(spectral_rms_slope(g, c) ==
        Approx(2e-6 * two_pi * 5 / 1e-3 / std::sqrt(2.0)).epsilon(1e-13));
}

TEST_CASE("a self-affine surface is reproducible by its seed", "[surfaces]") {
  const Grid g(32, 32, 1e-3, 1e-3);
  SelfAffineSpec spec;
  spec.rms_height = 1e-6;
  spec.seed = 7;
  const Field a = self_affine_surface(g, spec), b = self_affine_surface(g, spec);
  CHECK((a == b).all());
  spec.seed = 8;
  const Field c = self_affine_surface(g, spec);
  CHECK((a - c).abs().maxCoeff() > 0.1e-6);
}

TEST_CASE("self-affine surfaces refuse bad specs", "[surfaces]") {
  const Grid g(32, 32, 1e-3, 1e-3);
  SelfAffineSpec ok;
  ok.rms_height = 1e-6;
  const auto refused = [&](auto edit) {
    SelfAffineSpec s = ok;
    edit(s);
    CHECK_THROWS_AS(self_affine_surface(g, s), InvalidArgument);
  };
  refused([](SelfAffineSpec& s) { s.hurst = 0.0; });
  refused([](SelfAffineSpec& s) { s.hurst = 1.5; });
  refused([](SelfAffineSpec& s) { s.rms_slope = 0.1; });     // both
  refused([](SelfAffineSpec& s) { s.rms_height.reset(); });  // neither
  refused([](SelfAffineSpec& s) { s.rms_height = -1.0; });
  refused([&](SelfAffineSpec& s) { s.short_cutoff = g.dx(); });  // below Nyquist
  refused([](SelfAffineSpec& s) { s.long_cutoff = 1e-5; });      // below the short cut-off
  CHECK_THROWS_AS(self_affine_surface(Grid(33, 32, 1e-3, 1e-3), ok), InvalidArgument);
}

TEST_CASE("self-affine surfaces refuse rms values that overflow or underflow", "[surfaces]") {
  const Grid g(32, 32, 1e-3, 1e-3);
  const auto spec = [](std::optional<double> height, std::optional<double> slope) {
    SelfAffineSpec s;
    s.rms_height = height;
    s.rms_slope = slope;
    return s;
  };
  // A denormal height was scaled to zeros; a slope of 1e300 to heights whose squares overflow.
  CHECK_THROWS_AS(self_affine_surface(g, spec(1e-320, {})), InvalidArgument);
  CHECK_THROWS_AS(self_affine_surface(g, spec(1.5 * max_rms_height, {})), InvalidArgument);
  CHECK_THROWS_AS(self_affine_surface(g, spec({}, 1e300)), InvalidArgument);
  CHECK_THROWS_AS(self_affine_surface(g, spec({}, 1.5 * max_rms_slope)), InvalidArgument);
  // In its own range, but its surface would be far below a femtometre on a millimetre domain.
  CHECK_THROWS_AS(self_affine_surface(g, spec({}, 1e-14)), InvalidArgument);
  // The limits themselves are made, finite and as asked.
  for (const double h : {min_rms_height, max_rms_height}) {
    const Field z = self_affine_surface(g, spec(h, {}));
    CHECK(z.isFinite().all());
    CHECK(std::sqrt(z.square().mean()) == Approx(h).epsilon(1e-13));
  }
  const Field steep = self_affine_surface(g, spec({}, max_rms_slope));
  CHECK(steep.isFinite().all());
  CHECK(spectral_rms_slope(g, steep) == Approx(max_rms_slope).epsilon(1e-13));
  // The check names the values as its caller does (the command line: its flags).
  CHECK_THROWS_WITH(check_self_affine_spec(g, spec(1e-320, {}), "--rms-height", "--rms-slope"),
                    Catch::Contains("--rms-height"));
  CHECK_THROWS_WITH(check_self_affine_spec(g, spec({}, 1e-14), "--rms-height", "--rms-slope"),
                    Catch::Contains("--rms-slope"));
}
