#pragma once
// The plan of the split kernel: every parameter of the construction, chosen from the grid, the FRF
// and the options (split_frf_kernel.hpp), and the three parts that fill the kernel's quarter:
// the singular terms (a) + (b), the long range R w and the short range R (1 - w) of the remainder
// (docs/theory.md 4.5).
#include <algorithm>
#include <vector>

#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/kernels/split_kernel/detail/remainder.hpp"
#include "core/grid.hpp"
#include "core/types.hpp"
#include "frf/frf.hpp"

namespace coatfft::detail::split {

// The long part's rule along one axis of the cells: `sub` panels of `nodes` Gauss-Legendre points
// per cell, or panels graded away from the origin (graded_rule) where more than
// max_uniform_panels would be needed.
struct AxisQuadrature {
  int sub = 1;
  int nodes = 2;
  bool graded = false;
};

// One axis of the short-range lattice: half period h cells (0: a wide axis, add_short_range) and
// the alias order folded.
struct LatticeAxis {
  std::ptrdiff_t h = 0;
  int p_max = 0;
  bool capped = false;  // the fold needed more than max_alias_order
};

struct SplitPlan {
  // The grid and the options.
  std::ptrdiff_t nx = 0;
  std::ptrdiff_t ny = 0;
  double dx = 0.0;
  double dy = 0.0;
  double lx = 0.0;
  double ly = 0.0;
  double d_min = 0.0;   // min(dx, dy)
  double d_max = 0.0;   // max(dx, dy)
  double near_r = 0.0;  // 32 d_max: closed forms inside, smooth over a cell outside
  double tolerance = 0.0;
  double log_tol = 0.0;  // ln(1 / tolerance)
  int max_alias_order = 0;
  int threads = 1;
  // The split H = Cinf/k + A exp(-beta k)/k + R(k), A = C0 - Cinf.
  double c0 = 0.0;
  double c_inf = 0.0;
  double A = 0.0;
  double c_max = 0.0;  // max(C0, Cinf): the scale of every tolerance
  double beta = 0.0;
  bool remainder_zero = false;
  Remainder remainder;  // R, tabulated in log k (unless remainder_zero)
  double k_lo = 0.0;    // below: R constant
  double k_r = 0.0;     // beyond: |R| k <= tolerance c_max
  // The window split R = R w + R (1 - w).
  double sigma = 0.0;  // 0: periodic route, inf: Hankel route
  double s_c = 0.0;    // (sigma k)^2 beyond which w < tolerance
  double k_c = 0.0;    // beyond: R w negligible
  bool long_range = false;
  bool short_range = false;
  // Axes along which a cell is >= 128 sigma long (wide_cells): the short-range kernel lies
  // within the cell's own row, so the lattice along that axis collapses to its k = 0 term
  // (add_short_range).
  bool wide_x = false;
  bool wide_y = false;
  LatticeAxis lattice_x;
  LatticeAxis lattice_y;
  double lattice_entries = 0.0;  // of the short-range fold (require_lattice)
  double lattice_limit = 0.0;    // max_lattice_entries times the ranks that share the lattice
  // The long-range part: Hankel panels in k, radial steps, and the rule over each cell.
  std::vector<double> panel_edges;  // of the uniform table
  double r_max = 0.0;               // the domain's diagonal plus the stencil's reach
  double r_uniform = 0.0;           // the uniform table's end; beyond, the logarithmic tail
  double dr = 0.0;
  double ell = 0.0;  // the long-range kernel is smooth on this length
  AxisQuadrature quad_x;
  AxisQuadrature quad_y;
  bool stencil = false;  // far cells by point values and the cell-average stencil
};

// Gauss-Legendre points per panel of the long range's Hankel transform (hankel_panel_edges).
inline constexpr int hankel_panel_nodes = 16;

// Largest number of lattice entries (doubles) of the short-range fold: 2^27, 1 GiB.
inline constexpr double max_lattice_entries = 134217728.0;

// A lattice that would not fit is refused before it is allocated: a sigma given by the caller
// that is huge against a cell, or a grid of more than ~11585^2 cells (the lattice covers every
// offset of the domain); the automatic sigma keeps the half sizes <= max(2n, 96).
void require_lattice(const SplitPlan& p);

// Panels of the Hankel transform: geometric (halving) from the first uniform panel down to R's
// smallest scale, then uniform of width <= 2 pi / r_max (one J0 period at r_max) up to k_c.
std::vector<double> hankel_panel_edges(double k_c, double r_max, double k_lo);

// Gauss-Legendre points per panel for a panel `ratio` times shorter than the length on which the
// kernel is smooth. The n-point error on a panel of width w is about c_n (w/(sqrt(2) ell))^(2n)
// with c_2 = 2e-4, c_3 = 7e-7, c_4 = 7e-9, c_5 = 3e-11, c_6 = 2e-12: ~1e-13 relative.
int nodes_for_ratio(double ratio);

// The plan of the kernel of `frf` on `grid` (InvalidArgument for bad options or FRF constants);
// its lattice is held by `lattice_ranks` processes (a distributed kernel's), each a share.
SplitPlan make_split_plan(const Grid& grid, const Frf& frf, const SplitKernelOptions& options,
                          int lattice_ranks = 1);

// Rows [y0, y0 + rows) of the kernel's quarter K(i, j), 0 <= i <= nx, row j at values + (j - y0)
// (nx + 1), x fastest (a Field (nx + 1, rows)'s layout). The serial kernel fills the whole quarter
// (y0 = 0, ny + 1 rows); a rank of a distributed operator fills its own rows
// (distributed/distributed_split_kernel.cpp). Rows from ny on are never used by the convolution
// and are left to the caller.
struct QuarterRows {
  double* values = nullptr;
  std::ptrdiff_t nx = 0;
  std::ptrdiff_t y0 = 0;
  std::ptrdiff_t rows = 0;

  // The rows j < ny held here: [begin, end).
  std::ptrdiff_t begin(const SplitPlan& p) const { return std::min(y0, p.ny); }
  std::ptrdiff_t end(const SplitPlan& p) const { return std::min(y0 + rows, p.ny); }
  double* row(std::ptrdiff_t j) const { return values + (j - y0) * (nx + 1); }
};

// What the plan chose, into the report (split_frf_kernel's diagnostics).
void report_plan(const SplitPlan& p, SplitKernelReport& rep);

// (a) + (b) at every offset of `quarter`, or at the near cells only on the stencil route
// (singular_terms.cpp).
void assign_singular_terms(const SplitPlan& p, QuarterRows quarter);

// Adds (c) R w, the long range, by its Hankel table and a rule over each cell (long_range.cpp).
void add_long_range(const SplitPlan& p, QuarterRows quarter, std::vector<double>& spare,
                    SplitKernelReport& rep);

// Adds (c) R (1 - w), the short range, on a periodic lattice with the aliases folded
// (short_range.cpp): the whole lattice on this process.
void add_short_range(const SplitPlan& p, QuarterRows quarter, std::vector<double>& spare,
                     SplitKernelReport& rep);

// The short range's lattice, for a caller that transforms it itself (a distributed one): sx x sy
// entries (1 along a wide axis); after the 2-D DCT-I of the fold, quarter(i, j) += norm * the
// entry (i, j) for i < mx, j < my (mx = 1 or my = 1 along a wide axis: that axis keeps its cell's
// row only). `empty`: both axes wide, nothing to add.
struct ShortRangeLattice {
  std::ptrdiff_t sx = 1;
  std::ptrdiff_t sy = 1;
  std::ptrdiff_t mx = 0;
  std::ptrdiff_t my = 0;
  double norm = 0.0;
  bool empty = true;
};
ShortRangeLattice short_range_lattice(const SplitPlan& p);

// The alias fold of lattice rows [n0, n0 + count) into fold[(n - n0) * sx + m], every entry
// (short_range.cpp).
void fold_lattice_rows(const SplitPlan& p, std::ptrdiff_t n0, std::ptrdiff_t count, double* fold);

}  // namespace coatfft::detail::split
