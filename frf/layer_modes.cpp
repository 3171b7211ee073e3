#include "frf/layer_modes.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/error.hpp"
#include "frf/detail/hyperbolic_series.hpp"

namespace coatfft {

namespace {

using Medium = detail::ModeMedium;
using Matrix64 = Eigen::Matrix<double, 6, 4>;
using Matrix32 = Eigen::Matrix<double, 3, 2>;

// The global systems' matrices and amplitudes (columns: unit q~, unit p for P-SV) of a stack of
// `Coatings` coatings: 4 unknowns per coating and 2 for the substrate (P-SV), 2 and 1 (SH). Up to
// three coatings they have fixed sizes: on the stack, and factorized by Eigen's fixed-size code.
// One solve per wavenumber dominates the stress and traction kernels of coated bodies; with
// dynamic sizes it allocated a dozen small heap blocks, and with dynamic sizes of a fixed maximum
// it went through LU's blocked path and general triangular solves (a third of a coated traction
// kernel's set-up, three quarters of it under AddressSanitizer).
template <int Coatings>
struct System {
  static constexpr int kPsv = Coatings == Eigen::Dynamic ? Eigen::Dynamic : 4 * Coatings + 2;
  static constexpr int kSh = Coatings == Eigen::Dynamic ? Eigen::Dynamic : 2 * Coatings + 1;
  using PsvMatrix = Eigen::Matrix<double, kPsv, kPsv>;
  using ShMatrix = Eigen::Matrix<double, kSh, kSh>;
  using Psv = Eigen::Matrix<double, kPsv, 2>;
  using Sh = Eigen::Matrix<double, kSh, 1>;
};
// A half-space alone (2 P-SV unknowns, 1 SH): its amplitudes in arrays as wide as a coating's,
// since fields_at reads a width chosen at run time, which the compiler cannot bound.
template <>
struct System<0> {
  using PsvMatrix = Eigen::Matrix2d;
  using ShMatrix = Eigen::Matrix<double, 1, 1>;
  using Psv = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::ColMajor, 4, 2>;
  using Sh = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 2, 1>;
};

// exp(-s) underflows beyond ~745; there exp(-s) and s exp(-s) are set to 0 explicitly, so that
// s exp(-s) is never inf * 0 (s = +inf stands for "no bottom pair": the substrate).
constexpr double kExpUnderflow = 700.0;
// Coatings with k h above this use the decaying pairs of docs/theory.md §2.1 (exp(-kh) < 0.37:
// well separated), those below it their mid-plane state (mid_plane_psv_rows, cosh(kh/2) <= 1.13);
// both are accurate around 1.
constexpr double kThinKh = 1.0;
using detail::min_kh;

// P-SV rows: (U, W, szz, sxz~, sxx, syy) with U = 2 mu k ux~, W = 2 mu k uz (docs/theory.md §2.1
// and the sxx, syy rows of Barber's form, §2.7). SH rows: (mu k u_T, sTz, sLT).
enum PsvRow { kU = 0, kW = 1, kSzz = 2, kSxz = 3, kSxx = 4, kSyy = 5 };

struct Decay {
  double e, se;  // exp(-s), s exp(-s)
};
Decay decay(double s) {
  if (!(s < kExpUnderflow)) return {0.0, 0.0};
  const double e = std::exp(-s);
  return {e, s * e};
}

bool is_substrate(const Medium& m) {
  return std::isinf(m.thickness);
}

// k h_j of a coating (clamped, see min_kh); +inf for the substrate.
double reduced_thickness(const Medium& m, double k) {
  return is_substrate(m) ? m.thickness : std::max(k * m.thickness, min_kh);
}

// The P-SV rows of the decaying pairs at s = k zeta (top pair, unknowns A, B) and r = k eta
// (bottom pair, C, D), docs/theory.md §2.1 and §2.7; r = +inf (the substrate) zeroes the C, D
// columns.
Matrix64 pair_psv_rows(double nu, double s, double r) {
  const Decay t = decay(s), b = decay(r);
  const double kap = 3.0 - 4.0 * nu, a = 2.0 * (1.0 - nu), c = 1.0 - 2.0 * nu, d = 2.0 * nu;
  Matrix64 rows;
  rows << t.e, t.se, b.e, -b.se,                        // U
      -t.e, -t.se - kap * t.e, b.e, -b.se - kap * b.e,  // W
      t.e, t.se + a * t.e, b.e, -b.se - a * b.e,        // szz
      -t.e, -t.se - c * t.e, b.e, -b.se - c * b.e,      // sxz~
      -t.e, -t.se + d * t.e, -b.e, b.se - d * b.e,      // sxx
      0.0, d * t.e, 0.0, -d * b.e;                      // syy
  return rows;
}

// The P-SV rows of a thin coating (k h <= kThinKh) whose unknowns are its state (U, W, szz, sxz~)
// at the mid-plane: the propagator P(x) = Phi(x) Phi(0)^-1 of docs/theory.md §2.4 at x = k times
// the distance below the mid-plane (|x| <= 1/2), and sxx = (nu szz - U)/(1 - nu) (Hooke's law
// with eps_yy = 0), syy = nu (sxx + szz). The two decaying pairs of a thin layer are nearly the
// same functions and its response lives in their differences (1 - exp(-kh) for a layer sliding on
// a frictionless interface, sinh t - t for its bending), which the pairs would form from rounded
// exponentials; here they are exact entries (x cosh x - sinh x from its series).
Matrix64 mid_plane_psv_rows(double nu, double x) {
  const double g = 1.0 / (2.0 * (1.0 - nu)), k1 = 1.0 - 2.0 * nu;
  const double c = std::cosh(x), s = std::sinh(x), zs = x * s, zc = x * c;
  const double w = std::copysign(detail::x_cosh_minus_sinh(std::abs(x)), x);
  Matrix64 rows;
  rows.topRows<4>() << c + g * zs, -g * (k1 * s + zc), -g * zs, g * ((3.0 - 4.0 * nu) * s + zc),
      g * (w + 2.0 * nu * s), c - g * zs, g * (2.0 * k1 * s - w), g * zs,  //
      g * zs, -g * w, c - g * zs, g * (k1 * s + zc),                       //
      g * (zc + s), -g * zs, -g * (w + 2.0 * nu * s), c + g * zs;
  rows.row(kSxx) = (nu * rows.row(kSzz) - rows.row(kU)) / (1.0 - nu);
  rows.row(kSyy) = nu * (rows.row(kSxx) + rows.row(kSzz));
  return rows;
}

// SH rows (mu k u_T, sTz, sLT) of docs/theory.md §2.7: decaying pairs (a, c), or for a thin
// coating its mid-plane state (V, tau) = (mu k u_T, sTz), carried by V' = tau, tau' = V.
Matrix32 pair_sh_rows(double s, double r) {
  const Decay t = decay(s), b = decay(r);
  Matrix32 rows;
  rows << t.e, b.e, -t.e, b.e, t.e, b.e;
  return rows;
}
Matrix32 mid_plane_sh_rows(double x) {
  const double c = std::cosh(x), s = std::sinh(x);
  Matrix32 rows;
  rows << c, s, s, c, c, s;
  return rows;
}

// The rows of medium m at s = k zeta, r = k eta in its unknowns. The basis depends on the medium
// and k only, never on the depth, so that assembly and evaluation agree.
Matrix64 psv_rows(const Medium& m, double k, double s, double r) {
  if (!is_substrate(m) && reduced_thickness(m, k) <= kThinKh) {
    return mid_plane_psv_rows(m.nu, 0.5 * (s - r));
  }
  return pair_psv_rows(m.nu, s, r);
}
Matrix32 sh_rows(const Medium& m, double k, double s, double r) {
  if (!is_substrate(m) && reduced_thickness(m, k) <= kThinKh)
    return mid_plane_sh_rows(0.5 * (s - r));
  return pair_sh_rows(s, r);
}

// Unknowns per medium: 4 per coating and 2 for the substrate (P-SV), 2 and 1 (SH).
Eigen::Index psv_width(const Medium& m) {
  return is_substrate(m) ? 2 : 4;
}
Eigen::Index sh_width(const Medium& m) {
  return is_substrate(m) ? 1 : 2;
}

// Adds scale * row (its first `width` entries) to M at (i, col).
template <typename Matrix, typename Row>
void add(Matrix& M, Eigen::Index i, Eigen::Index col, Eigen::Index width,
         const Eigen::MatrixBase<Row>& row, double scale) {
  M.block(i, col, 1, width) += scale * row.head(width);
}

// The global matrix of docs/theory.md §2.4 for the P-SV mode: 2 surface rows, then 4 per
// interface, unknowns medium by medium. Displacement rows (2 mu k u) are divided by their mu and
// multiplied by the smaller mu of the two media, so that every entry is <= 1 in magnitude (row
// equilibration keeps partial pivoting meaningful for any modulus contrast).
template <typename Matrix>
Matrix psv_matrix(const std::vector<Medium>& media, double k) {
  const std::size_t n_layers = media.size() - 1;
  const auto n = Eigen::Index(4 * n_layers + 2);
  Matrix M = Matrix::Zero(n, n);
  const Matrix64 top = psv_rows(media[0], k, 0.0, reduced_thickness(media[0], k));
  add(M, 0, 0, psv_width(media[0]), top.row(kSzz), 1.0);  // szz(0) = -p
  add(M, 1, 0, psv_width(media[0]), top.row(kSxz), 1.0);  // sxz~(0) = -q~
  for (std::size_t j = 0; j < n_layers; ++j) {
    const Medium& a = media[j];
    const Medium& b = media[j + 1];
    const Matrix64 above = psv_rows(a, k, reduced_thickness(a, k), 0.0);
    const Matrix64 below = psv_rows(b, k, 0.0, reduced_thickness(b, k));
    const auto i = Eigen::Index(2 + 4 * j), ca = Eigen::Index(4 * j), cb = ca + 4;
    const Eigen::Index wb = psv_width(b);
    const double mu_min = std::min(a.mu, b.mu);
    const auto continuous = [&](Eigen::Index row, PsvRow q, double sa, double sb) {
      add(M, row, ca, 4, above.row(q), sa);
      add(M, row, cb, wb, below.row(q), -sb);
    };
    if (a.interface_below == Interface::bonded) {  // u, szz, sxz~ continuous
      continuous(i, kU, mu_min / a.mu, mu_min / b.mu);
      continuous(i + 1, kW, mu_min / a.mu, mu_min / b.mu);
      continuous(i + 2, kSzz, 1.0, 1.0);
      continuous(i + 3, kSxz, 1.0, 1.0);
    } else {  // uz, szz continuous; sxz~ = 0 on both faces
      continuous(i, kW, mu_min / a.mu, mu_min / b.mu);
      continuous(i + 1, kSzz, 1.0, 1.0);
      add(M, i + 2, ca, 4, above.row(kSxz), 1.0);
      add(M, i + 3, cb, wb, below.row(kSxz), 1.0);
    }
  }
  return M;
}

// The anti-plane (SH) system of docs/theory.md §2.7: sTz(0) = -q_T, then per interface either
// u_T and sTz continuous (bonded; u rows scaled as in psv_matrix) or sTz = 0 on both faces.
template <typename Matrix>
Matrix sh_matrix(const std::vector<Medium>& media, double k) {
  const std::size_t n_layers = media.size() - 1;
  const auto n = Eigen::Index(2 * n_layers + 1);
  Matrix M = Matrix::Zero(n, n);
  const Matrix32 top = sh_rows(media[0], k, 0.0, reduced_thickness(media[0], k));
  add(M, 0, 0, sh_width(media[0]), top.row(1), 1.0);
  for (std::size_t j = 0; j < n_layers; ++j) {
    const Medium& a = media[j];
    const Medium& b = media[j + 1];
    const Matrix32 above = sh_rows(a, k, reduced_thickness(a, k), 0.0);
    const Matrix32 below = sh_rows(b, k, 0.0, reduced_thickness(b, k));
    const auto i = Eigen::Index(1 + 2 * j), ca = Eigen::Index(2 * j), cb = ca + 2;
    const Eigen::Index wb = sh_width(b);
    if (a.interface_below == Interface::bonded) {
      const double mu_min = std::min(a.mu, b.mu);
      add(M, i, ca, 2, above.row(0), mu_min / a.mu);
      add(M, i, cb, wb, below.row(0), -mu_min / b.mu);
      add(M, i + 1, ca, 2, above.row(1), 1.0);
      add(M, i + 1, cb, wb, below.row(1), -1.0);
    } else {
      add(M, i, ca, 2, above.row(1), 1.0);
      add(M, i + 1, cb, wb, below.row(1), 1.0);
    }
  }
  return M;
}

// Amplitudes for unit q~ and unit p (P-SV) and unit q_T (SH): the load enters the surface rows
// only, szz(0) = -p, sxz~(0) = -q~, sTz(0) = -q_T. Partial pivoting suffices on the equilibrated
// rows (docs/theory.md §2.7 lists the measured accuracy).
template <typename S>
typename S::Psv solve_psv(const std::vector<Medium>& media, double k) {
  using Matrix = typename S::PsvMatrix;
  const Eigen::PartialPivLU<Matrix> lu(psv_matrix<Matrix>(media, k));
  // One column at a time: Eigen solves a vector of a small fixed size unrolled, where two
  // columns take its general blocked triangular solve.
  using Column = Eigen::Matrix<double, Matrix::RowsAtCompileTime, 1, Eigen::ColMajor,
                               Matrix::MaxRowsAtCompileTime, 1>;
  const Eigen::Index n = lu.rows();
  typename S::Psv amplitudes(n, 2);
  amplitudes.col(0) = lu.solve(-Column::Unit(n, 1));
  amplitudes.col(1) = lu.solve(-Column::Unit(n, 0));
  return amplitudes;
}

template <typename S>
typename S::Sh solve_sh(const std::vector<Medium>& media, double k) {
  const auto M = sh_matrix<typename S::ShMatrix>(media, k);
  typename S::Sh rhs = S::Sh::Zero(M.rows());
  rhs(0) = -1.0;
  return M.partialPivLu().solve(rhs);
}

// The fields of docs/theory.md §2.7 at depth z in medium j: its rows at s = k zeta, r = k eta
// times its amplitudes; displacements from the 2 mu k u (P-SV) and mu k u_T (SH) rows.
template <typename Psv, typename Sh>
ModeFields fields_at(const std::vector<Medium>& media, std::size_t j, double k, double z,
                     const Psv& psv, const Sh& sh) {
  const Medium& m = media[j];
  const double s = k * (z - m.top);
  const double r = is_substrate(m) ? m.thickness : std::max(k * (media[j + 1].top - z), 0.0);
  const Eigen::Index w = psv_width(m);
  const Eigen::Matrix<double, 6, 2> v =
      psv_rows(m, k, s, r).leftCols(w) * psv.middleRows(Eigen::Index(4 * j), w);
  const Eigen::Index ws = sh_width(m);
  const Eigen::Vector3d t = sh_rows(m, k, s, r).leftCols(ws) * sh.segment(Eigen::Index(2 * j), ws);
  const double to_u = 1.0 / (2.0 * m.mu * k);
  return {v(kU, 1) * to_u, v(kW, 1) * to_u, v(kSzz, 1),        v(kSxz, 1), v(kSxx, 1),
          v(kSyy, 1),      v(kU, 0) * to_u, v(kW, 0) * to_u,   v(kSzz, 0), v(kSxz, 0),
          v(kSxx, 0),      v(kSyy, 0),      t(0) / (m.mu * k), t(1),       t(2)};
}

}  // namespace

LayerModes::LayerModes(const LayerStack& stack) : stack_(stack) {
  const std::vector<double>& interfaces = stack.interface_depths();
  for (std::size_t i = 0; i < stack.coatings().size(); ++i) {
    const Coating& coating = stack.coatings()[i];
    const Material& mat = coating.material;
    media_.push_back({i == 0 ? 0.0 : interfaces[i - 1], coating.thickness, mat.poisson_ratio(),
                      mat.shear_modulus(), coating.interface_below});
  }
  const Material& sub = stack.substrate();
  media_.push_back({stack.total_thickness(), std::numeric_limits<double>::infinity(),
                    sub.poisson_ratio(), sub.shear_modulus(), Interface::bonded});
}

std::vector<ModeFields> LayerModes::at(double k, std::span<const double> depths,
                                       InterfaceSide side) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "LayerModes: k = ", k,
                  " rad/m, but the wavenumber must be finite and > 0");
  for (std::size_t i = 0; i < depths.size(); ++i) {
    COATFFT_REQUIRE(std::isfinite(depths[i]) && depths[i] >= 0, "LayerModes: depth ", i, " = ",
                    depths[i], " m, but depths must be finite and >= 0");
  }
  switch (media_.size() - 1) {
    case 0:
      return solve_at<System<0>>(k, depths, side);
    case 1:
      return solve_at<System<1>>(k, depths, side);
    case 2:
      return solve_at<System<2>>(k, depths, side);
    case 3:
      return solve_at<System<3>>(k, depths, side);
    default:
      return solve_at<System<Eigen::Dynamic>>(k, depths, side);
  }
}

template <typename S>
std::vector<ModeFields> LayerModes::solve_at(double k, std::span<const double> depths,
                                             InterfaceSide side) const {
  const typename S::Psv psv = solve_psv<S>(media_, k);
  const typename S::Sh sh = solve_sh<S>(media_, k);
  std::vector<ModeFields> fields;
  fields.reserve(depths.size());
  for (const double z : depths) {
    // At an interface, its own depth: the fields of either side are then those of the interface
    // whatever rounding the given depth carries.
    const DepthLocation at = stack_.locate(z, side);
    fields.push_back(fields_at(media_, at.layer, k, at.depth, psv, sh));
  }
  return fields;
}

}  // namespace coatfft
