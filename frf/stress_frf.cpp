#include "frf/stress_frf.hpp"

#include <cmath>

namespace coatfft {

namespace {

using C = std::complex<double>;
constexpr C I{0.0, 1.0};

// One load's field in the frame of k: L along k, T across it, z into the body.
struct ModeFrame {
  C sLL, sTT, szz, sTz, sLz, sLT, uL, uT, uz;
};

// Unit pressure, unit q_L (traction along k) and unit q_T (across k): the physical mode fields of
// frf/layer_modes.hpp from the real coefficients.
ModeFrame pressure_mode(const ModeFields& m) {
  return {m.sLL_p, m.sTT_p, m.szz_p, 0.0, I * m.sLz_p, 0.0, I * m.uL_p, 0.0, m.uz_p};
}
ModeFrame in_plane_mode(const ModeFields& m) {
  return {-I * m.sLL_q, -I * m.sTT_q, -I * m.szz_q, 0.0, m.sLz_q, 0.0, m.uL_q, 0.0, -I * m.uz_q};
}
ModeFrame anti_plane_mode(const ModeFields& m) {
  return {0.0, 0.0, 0.0, m.sTz_t, 0.0, I * m.sLT_t, 0.0, m.uT_t, 0.0};
}

ModeFrame combine(const ModeFrame& a, double wa, const ModeFrame& b, double wb) {
  return {wa * a.sLL + wb * b.sLL, wa * a.sTT + wb * b.sTT, wa * a.szz + wb * b.szz,
          wa * a.sTz + wb * b.sTz, wa * a.sLz + wb * b.sLz, wa * a.sLT + wb * b.sLT,
          wa * a.uL + wb * b.uL,   wa * a.uT + wb * b.uT,   wa * a.uz + wb * b.uz};
}

// The tensor rotation from (L, T) to (x, y) with e_L = (cx, cy), e_T = (-cy, cx).
void rotate_into(const ModeFrame& f, double cx, double cy, int load, StressFrf& out) {
  out.stress[s_xx][load] = cx * cx * f.sLL + cy * cy * f.sTT - 2.0 * cx * cy * f.sLT;
  out.stress[s_yy][load] = cy * cy * f.sLL + cx * cx * f.sTT + 2.0 * cx * cy * f.sLT;
  out.stress[s_zz][load] = f.szz;
  out.stress[s_yz][load] = cy * f.sLz + cx * f.sTz;
  out.stress[s_xz][load] = cx * f.sLz - cy * f.sTz;
  out.stress[s_xy][load] = cx * cy * (f.sLL - f.sTT) + (cx * cx - cy * cy) * f.sLT;
  out.displacement[0][load] = cx * f.uL - cy * f.uT;
  out.displacement[1][load] = cy * f.uL + cx * f.uT;
  out.displacement[2][load] = f.uz;
}

}  // namespace

StressFrf stress_frf(const ModeFields& m, double cx, double cy) {
  const ModeFrame q_l = in_plane_mode(m);
  const ModeFrame q_t = anti_plane_mode(m);
  StressFrf out;
  rotate_into(pressure_mode(m), cx, cy, load_p, out);
  // q_x = cx q_L - cy q_T and q_y = cy q_L + cx q_T.
  rotate_into(combine(q_l, cx, q_t, -cy), cx, cy, load_qx, out);
  rotate_into(combine(q_l, cy, q_t, cx), cx, cy, load_qy, out);
  return out;
}

StressFrf stress_frf_at_zero(const ModeFields& m0) {
  // Every entry of T4 is a polynomial in cx, cy of degree <= 4 times functions of |k|; the mean
  // over the circle of the directions is the average of the eight directions at multiples of
  // pi/4, exact for trigonometric polynomials of degree < 8.
  StressFrf mean;
  constexpr int kDirections = 8;
  for (int d = 0; d < kDirections; ++d) {
    const double angle = 2.0 * 3.14159265358979323846 * d / kDirections;
    const StressFrf f = stress_frf(m0, std::cos(angle), std::sin(angle));
    for (int c = 0; c < 6; ++c)
      for (int l = 0; l < 3; ++l) mean.stress[c][l] += f.stress[c][l] / double(kDirections);
    for (int c = 0; c < 3; ++c)
      for (int l = 0; l < 3; ++l)
        mean.displacement[c][l] += f.displacement[c][l] / double(kDirections);
  }
  return mean;
}

std::array<bool, 2> stress_frf_odd(int component, int load) {
  // Number of x and y indices of each component (xx, yy, zz, yz, xz, xy) and load (p, qx, qy).
  constexpr int kX[6] = {2, 0, 0, 0, 1, 1};
  constexpr int kY[6] = {0, 2, 0, 1, 0, 1};
  const int lx = load == load_qx ? 1 : 0;
  const int ly = load == load_qy ? 1 : 0;
  return {(kX[component] + lx) % 2 == 1, (kY[component] + ly) % 2 == 1};
}

}  // namespace coatfft
