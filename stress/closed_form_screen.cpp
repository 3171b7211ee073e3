#include "stress/detail/closed_form_screen.hpp"

#include <algorithm>

#include "stress/detail/principal_closed_form.hpp"
#include "stress/stress_invariants.hpp"

namespace coatfft::detail {

namespace {

// Cells per block: its four arrays (2 KiB each) and the components' slices stay in cache.
constexpr std::size_t kBlock = 256;

struct Block {
  std::array<double, kBlock> mises, tensile, tresca, largest;  // largest: |component|
};

// On x86-64 the closed forms are compiled for AVX-512 and AVX2 besides the baseline SSE2, the
// widest the processor has chosen when the library loads (target_clones): 5.2, 8.8 and 19.5 ns a
// cell on an AMD EPYC (a development measurement; docs/benchmarks.md, "The summary step", has
// the step's). Without fused multiply-adds (-ffp-contract=off, this file's option) every width
// computes the same values.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define COATFFT_WIDEST_VECTORS __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define COATFFT_WIDEST_VECTORS
#endif

// The closed forms of n cells into a block, vectorised, with each cell's largest |component|. The
// arrays are distinct (restrict: the compiler would otherwise check the pairs of them for
// overlap, and give up).
COATFFT_WIDEST_VECTORS void closed_forms(const double* __restrict xx, const double* __restrict yy,
                                         const double* __restrict zz, const double* __restrict yz,
                                         const double* __restrict xz, const double* __restrict xy,
                                         std::size_t n, double* __restrict mises,
                                         double* __restrict tensile, double* __restrict tresca,
                                         double* __restrict largest) {
  for (std::size_t k = 0; k < n; ++k) {
    mises[k] = von_mises_unscaled(xx[k], yy[k], zz[k], yz[k], xz[k], xy[k]);
    const std::array<double, 3> p = principal_closed_form(xx[k], yy[k], zz[k], yz[k], xz[k], xy[k]);
    tensile[k] = p[0];
    tresca[k] = 0.5 * (p[0] - p[2]);
    largest[k] = largest_component(xx[k], yy[k], zz[k], yz[k], xz[k], xy[k]);
  }
}

// A cell whose largest component lies beyond [1e-90, 1e90] Pa (or is not finite), by the public
// functions, which scale it first.
void redo_scaled(const StressVector& t, double& mises, double& tensile, double& tresca) {
  const std::array<double, 3> p = closed_form_principal_stresses(t);
  mises = von_mises(t);
  tensile = p[0];
  tresca = 0.5 * (p[0] - p[2]);
}

}  // namespace

ClosedFormScreen screen_cells(const std::array<const double*, 6>& components, std::size_t count,
                              double* mises_out) {
  const auto [xx, yy, zz, yz, xz, xy] = components;
  ClosedFormScreen out;
  double reach_tensile = -INFINITY, reach_tresca = -INFINITY;
  // Cells whose upper bound reaches the largest lower bound so far (which only grows, so this
  // holds every cell that reaches the final one), with their upper bounds.
  struct Upper {
    std::size_t cell;
    double tensile, tresca;
  };
  std::vector<Upper> maybe;
  Block b;
  for (std::size_t first = 0; first < count; first += kBlock) {
    const std::size_t n = std::min(kBlock, count - first);
    closed_forms(xx + first, yy + first, zz + first, yz + first, xz + first, xy + first, n,
                 b.mises.data(), b.tensile.data(), b.tresca.data(), b.largest.data());
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t c = first + k;
      if (!in_closed_form_range(b.largest[k]))
        redo_scaled({xx[c], yy[c], zz[c], yz[c], xz[c], xy[c]}, b.mises[k], b.tensile[k],
                    b.tresca[k]);
      out.finite = out.finite && std::isfinite(b.mises[k]);
      if (b.mises[k] > out.mises) {
        out.mises = b.mises[k];
        out.mises_cell = c;
      }
      // A generous bound on the closed form's error: 1e-6 of the largest component (about 2e-8
      // of it at worst, near a double root).
      const double error = 1e-6 * b.largest[k];
      reach_tensile = std::max(reach_tensile, b.tensile[k] - error);
      reach_tresca = std::max(reach_tresca, b.tresca[k] - error);
      const Upper u{c, b.tensile[k] + error, b.tresca[k] + error};
      if (u.tensile >= reach_tensile || u.tresca >= reach_tresca) maybe.push_back(u);
    }
    if (mises_out) std::copy_n(b.mises.data(), n, mises_out + first);
  }
  for (const Upper& u : maybe)
    if (u.tensile >= reach_tensile || u.tresca >= reach_tresca) out.candidates.push_back(u.cell);
  return out;
}

}  // namespace coatfft::detail
