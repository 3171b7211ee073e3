#include "validation/hertz_stress.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

// Hamilton (1983) writes his stresses in units of 3P/(2 pi a^2) = p0 (normal part) and
// 3Q/(2 pi a^2) = mu p0 (tangential part), lengths in units of a. In the form used here, that of
// the transcription in matscipy (Pastewka et al., Hertz.py), they are tension positive with z into
// the body and Q acting on the body in +x: the conventions of hertz_sliding_stress, so no sign is
// converted. The print was not re-read (its tangential sigma_y and tau_xy are said to carry
// misprints); instead every component of the expressions below was checked against Boussinesq's
// and Cerruti's point-force fields integrated over the contact, to 1e-14 p0
// (tests/test_hertz_stress.cpp). Auxiliaries (a = 1):
//   A = r^2 + z^2 - 1,  S = sqrt(A^2 + 4 z^2),  M = sqrt((S + A)/2),  N = sqrt((S - A)/2),
//   phi = atan(1/M);  M N = z and M^2 + N^2 = S.

namespace coatfft {
namespace {

using std::numbers::pi;

// Near the axis Hamilton's expressions divide by r^2 and r^4 numerators that vanish like r^2 and
// r^4: the tangential part loses ~ eps a^3/r^3 (1e-10 p0 at r = 1e-2 a, everything at 1e-5 a).
// There they are evaluated on truncated Taylor series in t along the ray (x, y) = t (cx, cy), on
// which a division by r^2 = t^2 is an exact shift and r = 0 is the constant term (the limit). The
// series converge for |t| < sqrt(1 + z^2) (the complex zeros of S), the scale of the loss too, so
// they are used for r < sqrt(1 + z^2)/4, where the 28 terms left after the shifts by t^4 leave
// < 1e-16 (0.25^28).
constexpr int kJetOrder = 32;
constexpr double kJetRadius = 0.25;  // of sqrt(1 + z^2): the radius below which the series are used

struct Jet {
  std::array<double, kJetOrder> c{};
};

Jet constant(double v) {
  Jet u;
  u.c[0] = v;
  return u;
}
Jet operator+(Jet u, const Jet& v) {
  for (int k = 0; k < kJetOrder; ++k) u.c[k] += v.c[k];
  return u;
}
Jet operator*(Jet u, double s) {
  for (double& v : u.c) v *= s;
  return u;
}
Jet operator-(const Jet& u) {
  return u * -1.0;
}
Jet operator-(const Jet& u, const Jet& v) {
  return u + (-v);
}
Jet operator+(Jet u, double s) {
  u.c[0] += s;
  return u;
}
Jet operator+(double s, const Jet& u) {
  return u + s;
}
Jet operator-(const Jet& u, double s) {
  return u + (-s);
}
Jet operator-(double s, const Jet& u) {
  return (-u) + s;
}
Jet operator*(double s, const Jet& u) {
  return u * s;
}
Jet operator/(const Jet& u, double s) {
  return u * (1.0 / s);
}
Jet operator*(const Jet& u, const Jet& v) {
  Jet w;
  for (int k = 0; k < kJetOrder; ++k)
    for (int j = 0; j <= k; ++j) w.c[k] += u.c[j] * v.c[k - j];
  return w;
}
// v(0) != 0: w v = u order by order.
Jet operator/(const Jet& u, const Jet& v) {
  Jet w;
  for (int k = 0; k < kJetOrder; ++k) {
    double s = u.c[k];
    for (int j = 1; j <= k; ++j) s -= v.c[j] * w.c[k - j];
    w.c[k] = s / v.c[0];
  }
  return w;
}
Jet operator/(double s, const Jet& v) {
  return constant(s) / v;
}
// g(0) > 0: f f = g order by order.
Jet sqrt(const Jet& g) {
  Jet f;
  f.c[0] = std::sqrt(g.c[0]);
  for (int k = 1; k < kJetOrder; ++k) {
    double s = g.c[k];
    for (int j = 1; j < k; ++j) s -= f.c[j] * f.c[k - j];
    f.c[k] = s / (2.0 * f.c[0]);
  }
  return f;
}
// f' = u' / (1 + u^2), integrated term by term.
Jet atan(const Jet& u) {
  Jet du;
  for (int k = 0; k + 1 < kJetOrder; ++k) du.c[k] = (k + 1) * u.c[k + 1];
  const Jet q = du / (1.0 + u * u);
  Jet f;
  f.c[0] = std::atan(u.c[0]);
  for (int k = 1; k < kJetOrder; ++k) f.c[k] = q.c[k - 1] / k;
  return f;
}
double evaluate(const Jet& u, double t) {
  double v = 0.0;
  for (int k = kJetOrder - 1; k >= 0; --k) v = v * t + u.c[k];
  return v;
}

// Division by r^2 of a numerator that vanishes like r^2: plain, or a shift of the series (its
// first two terms are zero up to rounding).
double over_r2(double u, double r2) {
  return u / r2;
}
Jet over_r2(const Jet& u, const Jet& /*r2 = t^2*/) {
  Jet w;
  for (int k = 2; k < kJetOrder; ++k) w.c[k - 2] = u.c[k];
  return w;
}

// Hamilton's auxiliaries at (x, y, z)/a; s_inv = 1/S, set to 0 at the contact edge on the surface
// (S = 0), where every term it enters is multiplied by z, M or N, all zero there: the limit.
template <class T>
struct FieldPoint {
  T x, y, x2, y2, r2, A, S, s_inv, M, N, phi;
  double z;
};

FieldPoint<double> plain_point(double x, double y, double z) {
  const double r2 = x * x + y * y, A = r2 + z * z - 1.0, S = std::hypot(A, 2.0 * z);
  // The root of the larger of S + A, S - A, the other from M N = z: no cancellation near z = 0.
  double M = 0.0, N = 0.0;
  if (A < 0) {
    N = std::sqrt((S - A) / 2.0);
    M = z / N;
  } else {
    M = std::sqrt((S + A) / 2.0);
    N = M > 0 ? z / M : 0.0;
  }
  return {x, y, x * x, y * y, r2, A, S, S > 0 ? 1.0 / S : 0.0, M, N, std::atan2(1.0, M), z};
}

// The same as series in t along the ray (cx, cy), cx^2 + cy^2 = 1. S(0) = 1 + z^2 and
// (S - A)(0) = 2: the roots and divisions are regular, also at z = 0 (M = z/N = 0).
FieldPoint<Jet> series_point(double cx, double cy, double z) {
  Jet x, y, r2;
  x.c[1] = cx;
  y.c[1] = cy;
  r2.c[2] = 1.0;
  const Jet A = r2 + (z * z - 1.0);
  const Jet S = sqrt(A * A + 4.0 * z * z);
  const Jet N = sqrt((S - A) / 2.0);
  const Jet M = z / N;
  return {x, y, x * x, y * y, r2, A, S, 1.0 / S, M, N, pi / 2 - atan(M), z};
}

// Normal part (Hamilton & Goodman 1966; Hamilton 1983), units p0.
template <class T>
std::array<T, 6> normal_part(const FieldPoint<T>& p, double nu) {
  const double z = p.z;
  const T B =
      (1 - nu) * z * z * p.N - (1 - 2 * nu) / 3 * (p.N * (p.S + 2.0 * p.A) + 1.0) - nu * z * p.M;
  const T zphi = (1 + nu) * z * p.phi;
  const T xx = zphi + over_r2(over_r2((p.y2 - p.x2) * B, p.r2) - p.N * (p.x2 + 2 * nu * p.y2) -
                                  z * p.M * p.x2 * p.s_inv,
                              p.r2);
  const T yy = zphi + over_r2(over_r2((p.x2 - p.y2) * B, p.r2) - p.N * (p.y2 + 2 * nu * p.x2) -
                                  z * p.M * p.y2 * p.s_inv,
                              p.r2);
  const T zz = z * p.M * p.s_inv - p.N;
  const T bracket = (1 - 2 * nu) * (2.0 / 3 * (p.N * (p.S + 2.0 * p.A) + 1.0) - p.N * p.r2 -
                                    z * (z * p.N + p.M)) +
                    z * (p.M - p.M * p.r2 * p.s_inv - z * p.N);
  const T xy = over_r2(over_r2(p.x * p.y * bracket, p.r2), p.r2);
  // z H/(G^2 + H^2) with G + iH = w (w + z + i), w = M + iN, |w|^2 = S: = z H / (S |w + z + i|^2),
  // finite at the contact edge where G = H = S = 0.
  const T H = 2.0 * p.M * p.N + p.M + z * p.N;
  const T Q = (p.M + z) * (p.M + z) + (p.N + 1.0) * (p.N + 1.0);
  const T q = z * p.s_inv * (p.N - z * H / Q);
  return {xx, yy, zz, -(p.y * q), -(p.x * q), xy};
}

// Tangential part (Hamilton 1983), units mu p0. Each r^-4 term is one numerator divided twice,
// the angular factors x^2/r^2 as O(1) quotients.
template <class T>
T tangential_xx(const FieldPoint<T>& p, double nu) {
  const double z = p.z, z2 = z * z;
  const T c = 1.5 - 2.0 * over_r2(p.x2, p.r2);
  const T m = c * (nu * (p.S - 2.0 * p.A) + z2) + z2 * p.x2 * p.s_inv + 1.75 * nu * p.r2 -
              2 * nu * p.x2 + p.r2;
  const T n = c * (-(1 - 2 * nu) * (p.S / 6 + p.A / 3) - 0.5 * (z2 + 3)) + p.x2 * p.s_inv -
              0.25 * nu * p.r2 - 1.75 * p.r2;
  const T num = p.x * (p.M * m + z * p.N * n + 4 * z / 3 * (1 - 2 * nu) * c);
  return over_r2(over_r2(num, p.r2), p.r2) - (nu / 4 + 1) * p.x * p.phi;
}

template <class T>
T tangential_yy(const FieldPoint<T>& p, double nu) {
  const double z = p.z, z2 = z * z;
  const T c = 0.5 - 2.0 * over_r2(p.y2, p.r2);
  const T m = c * (nu * (p.S - 2.0 * p.A + p.r2) + z2) + z2 * p.y2 * p.s_inv + 0.75 * nu * p.r2;
  const T n = c * (-(1 - 2 * nu) * (p.S / 6 + p.A / 3) - 0.5 * z2 - 1.5) + p.y2 * p.s_inv -
              0.75 * nu * p.r2 - 0.25 * p.r2;
  const T num = p.x * (p.M * m + z * p.N * n + 4 * z / 3 * (1 - 2 * nu) * c);
  return over_r2(over_r2(num, p.r2), p.r2) - 0.75 * nu * p.x * p.phi;
}

template <class T>
T tangential_xy(const FieldPoint<T>& p, double nu) {
  const double z = p.z, z2 = z * z;
  const T c = 0.5 - 2.0 * over_r2(p.x2, p.r2);
  const T m = z2 * p.x2 * p.s_inv + nu * ((p.S - 2.0 * p.A) * c - 2.0 * p.x2 + 0.25 * p.r2) +
              0.5 * p.r2 + z2 * c;
  const T n = c * ((2 * nu - 1) * (p.S / 6 + p.A / 3) - 0.5 * z2 - 1.5 - 0.5 * p.r2) +
              0.25 * nu * p.r2 + p.x2 * p.s_inv - 0.5 * p.y2 - 1.5 * p.x2;
  const T num = p.y * (p.M * m + z * p.N * n + 4 * z / 3 * (1 - 2 * nu) * c);
  return over_r2(over_r2(num, p.r2), p.r2) + 0.5 * (nu / 2 - 1) * p.y * p.phi;
}

template <class T>
std::array<T, 6> tangential_part(const FieldPoint<T>& p, double nu) {
  const double z = p.z, z2 = z * z;
  const T zz = 0.5 * z * over_r2(p.x * p.N * (1.0 - (p.r2 + (z2 + 1)) * p.s_inv), p.r2);
  const T yz_num = p.M * (0.5 + (0.5 * z2 - 1.5 - 0.5 * p.r2) * p.s_inv) +
                   0.5 * z * p.N * ((5 + z2 + p.r2) * p.s_inv - 3.0);
  const T yz = 0.5 * z * over_r2(over_r2(p.x * p.y * yz_num, p.r2), p.r2);
  const T xz_num = z * p.M * (1.0 + over_r2(p.x2, p.r2) - p.x2 * p.s_inv) +
                   p.N * (z2 - 0.75 * (p.S + 2.0 * p.A) - 0.75 - 0.25 * p.r2 +
                          0.5 * z2 * (0.5 - 2.0 * over_r2(p.x2, p.r2)));
  const T xz = 1.5 * z * p.phi + over_r2(xz_num, p.r2);
  return {tangential_xx(p, nu), tangential_yy(p, nu), zz, yz, xz, tangential_xy(p, nu)};
}

}  // namespace

StressTensor hertz_sliding_stress(double x, double y, double z, double p0, double a, double nu,
                                  double friction) {
  COATFFT_REQUIRE(std::isfinite(x) && std::isfinite(y), "hertz_sliding_stress: (x, y) = (", x, ", ",
                  y, ") m, but x and y must be finite");
  COATFFT_REQUIRE(std::isfinite(z) && z >= 0, "hertz_sliding_stress: z = ", z,
                  " m, but z must be finite and >= 0 (into the body)");
  COATFFT_REQUIRE(std::isfinite(p0), "hertz_sliding_stress: p0 = ", p0,
                  " Pa, but it must be finite");
  COATFFT_REQUIRE(std::isfinite(a) && a > 0, "hertz_sliding_stress: a = ", a,
                  " m, but a must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(nu) && nu > -1 && nu <= 0.5, "hertz_sliding_stress: nu = ", nu,
                  ", but nu must be in (-1, 0.5]");
  COATFFT_REQUIRE(std::isfinite(friction), "hertz_sliding_stress: friction = ", friction,
                  ", but it must be finite");
  const double xa = x / a, ya = y / a, za = z / a, r = std::hypot(xa, ya);
  std::array<double, 6> normal{}, tangential{};
  if (r < kJetRadius * std::sqrt(1.0 + za * za)) {
    // Any direction at r = 0: only the constant terms remain.
    const FieldPoint<Jet> p = r > 0 ? series_point(xa / r, ya / r, za) : series_point(1.0, 0.0, za);
    const std::array<Jet, 6> n = normal_part(p, nu), t = tangential_part(p, nu);
    for (int k = 0; k < 6; ++k) {
      normal[k] = evaluate(n[k], r);
      tangential[k] = evaluate(t[k], r);
    }
  } else {
    const FieldPoint<double> p = plain_point(xa, ya, za);
    normal = normal_part(p, nu);
    tangential = tangential_part(p, nu);
  }
  std::array<double, 6> s{};
  for (int k = 0; k < 6; ++k) s[k] = p0 * (normal[k] + friction * tangential[k]);
  return {s[0], s[1], s[2], s[3], s[4], s[5]};
}

}  // namespace coatfft
