#pragma once
// A real multiplier on the DFT of a periodic (nx, ny) grid: the r2c transform of a field, each
// mode times a real number, the c2r transform back. The periodic operator (its kernel's spectrum)
// and the contact solver's preconditioner (|k| or its adaptation) are both such filters on the
// same grid; they share one filter, its plans and its one spectrum buffer (the largest array of
// either, (nx/2 + 1) ny complex numbers: a field's memory), since neither needs it between its
// own applications (docs/scale.md, "Memory per cell").
#include <cstddef>
#include <memory>
#include <vector>

#include "../../../core/grid.hpp"
#include "../planning.hpp"

namespace coatfft::detail {

/// A real multiplier even in both frequencies (the DFT of a real kernel that is even in both
/// offsets, or a function of |k|): stored on the quarter 0 <= i <= nx/2, 0 <= j <= ny/2 of the
/// modes, x fastest; the mode (i, j) reads (i, min(j, ny - j)).
struct EvenMultiplier {
  EvenMultiplier() = default;
  EvenMultiplier(std::ptrdiff_t nx, std::ptrdiff_t ny)
      : hx(nx / 2 + 1), hy(ny / 2 + 1), values(static_cast<std::size_t>(hx * hy), 0.0) {}
  double& operator()(std::ptrdiff_t i, std::ptrdiff_t j) {
    return values[static_cast<std::size_t>(j * hx + i)];
  }
  double operator()(std::ptrdiff_t i, std::ptrdiff_t j) const {
    return values[static_cast<std::size_t>(j * hx + i)];
  }
  std::ptrdiff_t hx = 0, hy = 0;
  std::vector<double> values;
};

class SpectralFilter {
 public:
  /// Plans the r2c/c2r pair of `grid` in `precision` (`planning`, `threads` FFTW threads).
  static std::shared_ptr<SpectralFilter> create(const Grid& grid, Planning planning,
                                                Precision precision, int threads);
  virtual ~SpectralFilter() = default;

  /// out <- F^-1 [m F[in]] unnormalised (nx ny times the convolution: fold 1/(nx ny) into m);
  /// `in` and `out` (nx ny values each, x fastest) may be the same array. In double precision the
  /// transforms read and write the arrays themselves where their alignment is the planned one
  /// (otherwise through a buffer); in single precision fields are converted on the way.
  virtual void apply(const double* in, double* out, const EvenMultiplier& m) = 0;
  /// The real part of the DFT of `in` (even in both offsets: its DFT is real and even) times
  /// `scale`, computed in double precision whatever the filter's own.
  virtual EvenMultiplier even_spectrum(const double* in, double scale) = 0;

  const Grid& grid() const { return grid_; }
  Precision precision() const { return precision_; }

 protected:
  SpectralFilter(const Grid& grid, Precision precision) : grid_(grid), precision_(precision) {}

 private:
  Grid grid_;
  Precision precision_;
};

}  // namespace coatfft::detail
