#pragma once
// Preconditioner for the contact iteration: an approximate inverse of the half-space operator,
// z = F^-1 [ sigma(k) F[g] ] with sigma(k) = |k| (up to a constant) on the periodic nx x ny grid.
// The half-space compliance is 2/(E* k) (docs/conventions.md), so sigma K ~ identity, and the
// condition number of the preconditioned contact block stays nearly independent of N. The scale of
// sigma is irrelevant: the conjugate-gradient step length absorbs it.
//
// A coated body's k K^(k) runs from 2/E*_substrate (k -> 0) to 2/E*_coating (k -> inf), a ratio
// |k| leaves in the condition number: the iterations grow about as its square root
// (docs/contact.md, "Preconditioning"). On a periodic operator, whose symbol K^ is known exactly
// (the DFT of its coefficients), sigma = sqrt(|k| / K^), the geometric mean of |k| and the inverse
// symbol, takes the square root of that ratio on the whole grid (on contact blocks the measured
// gain is smaller, 0.6 to 1.1 times the iterations of |k|: docs/contact.md, "Stiffness
// contrast"). The inverse symbol itself, 1 / K^, is exact on the whole grid but not on a contact
// block of small patches, where its high wavenumbers, the coating's, weigh up to the ratio too
// much: measured before Powell's restart (polonsky_keer_iteration.cpp), it let the contact set
// cycle (no convergence in 3000 iterations at a ratio of 1000), where the geometric mean converged
// in 230-350.
#include <memory>

#include "contact/detail/solver_ranks.hpp"
#include "convolution/fft/detail/spectral_filter.hpp"
#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft::detail {

/// sigma(k) of the mode (i, j) (0 <= i <= nx/2, 0 <= j < ny, j the signed frequency) times
/// `norm`: |k|, and at k = 0 the inverse of the mean of 1/|k| over the central frequency cell.
double preconditioner_symbol(const Grid& grid, std::ptrdiff_t i, std::ptrdiff_t j, double norm);

class FourierPreconditioner final : public Preconditioner {
 public:
  /// Plans the periodic r2c/c2r pair on `grid` (`planning`, `threads` FFTW threads). Double
  /// precision: single was measured to give the same iteration counts at 512^2 and 1024^2 with
  /// transforms a third faster, but its rounding does not scale with the problem, so a contact
  /// scaled by c would no longer be c times the unscaled one to double's rounding
  /// (docs/contact.md, "Preconditioning").
  explicit FourierPreconditioner(const Grid& grid, int threads = 1,
                                 Planning planning = Planning::estimate);
  /// On the transforms of a periodic operator of the same grid (PeriodicOperator::
  /// spectral_filter, double precision), which the two share: no plans and no spectrum buffer of
  /// its own.
  explicit FourierPreconditioner(std::shared_ptr<SpectralFilter> filter);

  /// sigma <- sqrt(|k| / K^) (above), K^ the DFT of `kernel`, the coefficients of a periodic
  /// operator (SurfaceOperator::unit_response: K at the offsets 0 <= i < nx, 0 <= j < ny modulo
  /// the period). At k = 0, where the periodic kernel's sum vanishes, the |k| rule times the
  /// factor sqrt(1 / (|k| K^)) of the nearest mode. Returns false, keeping |k|, when a mode's K^
  /// (k != 0) is not finite and > 0 (no symmetric positive-definite operator).
  bool adapt_to_kernel(const Field& kernel);

  /// z <- F^-1 [sigma F[z]] in place; `z` has the grid's nx ny values, x fastest.
  /// sigma(k) = |k| [rad/m]; at k = 0, where |k| vanishes, sigma is the inverse of the mean of
  /// 1/|k| over the central frequency cell (docs/theory.md eq. 3.1), the same zero-frequency rule
  /// as g(0) of the spectral operators. Only the approach-controlled iteration sees this value:
  /// under load control the preconditioned field has zero mean.
  void apply(double* z) override;
  void apply(Field& field) { apply(field.data()); }

 private:
  Grid grid_;
  std::shared_ptr<SpectralFilter> filter_;
  EvenMultiplier sigma_;  // sigma(k) / (nx ny), FFTW's normalisation folded in
};

}  // namespace coatfft::detail
