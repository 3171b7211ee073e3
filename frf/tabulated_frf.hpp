#pragma once
// An FRF given as a table of H(k) (a body coatfft cannot model: graded or anisotropic coatings,
// a finite-element or measured response), usable by every FRF method of make_operator.
//
// Interpolation: the bounded, smooth function k H(k) (C0 at k -> 0, Cinf at k -> inf) against
// ln k by a natural cubic spline (GSL's gsl_interp_cspline; de Boor 1978, ch. IV): fourth order
// in the spacing of ln k. Measured on coatfft's own layered FRFs (stiff and soft coatings, bonded
// and frictionless, two three-layer stacks with a soft frictionless interlayer; tables over
// k h_total = 1e-8 .. 1e3, tests/test_tabulated_frf.cpp), log-spaced tables of n points per
// decade reproduce H between their points to a largest relative error of
//   n = 10: 1.4e-3,  n = 20: 5.9e-5,  n = 40: 3.3e-6,  n = 80: 2.0e-7,  n = 160: 1.3e-8
// (docs/frf.md), falling like (ln 10 / n)^4. A monotone Steffen interpolant (Steffen 1990) was
// measured too and rejected: third order, and flattened at the extrema of k H that layered
// bodies with a soft interlayer have (6.8e-5 at n = 160). Outside the table, k H is carried
// continuously to its limits:
//   k < k_min: k H = C0 + (k_min H_min - C0) k / k_min   (linear in k, the leading term of every
//              layered FRF's expansion H = C0/k + O(1));
//   k > k_max: k H = Cinf + (k_max H_max - Cinf) exp(1 - k / k_max)   (exponential, as the layered
//              FRFs' exp(-2 k h_top), never faster than theirs once k_max h_top > 1/2).
// C0 and Cinf not given are estimated as the end values k_min H_min and k_max H_max (the
// extensions then are constants); the estimate is refused unless k H varies by at most
// flatness_tolerance (relative) over the decade of k at that end of the table. C0 and Cinf given
// are checked against those end values: a ratio beyond limit_refusal_factor either way is a
// contradiction (a wrong unit, a wrong material, a table of another body) and refused; one
// beyond 1 + limit_warning_tolerance is kept with a warning (warnings()), since the extension
// then carries more of k H than the table does.
//
// Evaluation is const and thread-safe: no GSL accelerator is shared (each call searches the
// table by bisection).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frf.hpp"

namespace coatfft {

class TabulatedFrf final : public Frf {
 public:
  /// Fewest rows accepted.
  static constexpr std::size_t min_points = 5;
  /// Largest relative variation of k H over the end decade of k at which C0 (or Cinf) may be
  /// estimated from the table's end value: in the linear regime of small k that bounds the
  /// estimate's error by about flatness_tolerance / 9.
  static constexpr double flatness_tolerance = 1e-6;
  /// The largest ratio (either way) of a given c0 (c_inf) to the table's k H at its smallest
  /// (largest) k: beyond it, k H would have to change tenfold outside the table, which a table
  /// of a body's transition does not leave undone; the limit and the table contradict each other.
  static constexpr double limit_refusal_factor = 10.0;
  /// The relative difference of a given limit and the table's end above which a warning is given.
  static constexpr double limit_warning_tolerance = 0.01;

  /// k [rad/m]: finite, > 0, strictly ascending (also in ln k); H [m/Pa]: finite and > 0, one per
  /// k; at least min_points rows. c0, c_inf [m/Pa * rad/m]: finite and > 0 when given, within
  /// limit_refusal_factor of the table's end, else estimated (see above). Throws
  /// InvalidArgument naming the row (0-based) and the value, or the limit and both values.
  TabulatedFrf(std::vector<double> k, std::vector<double> H, std::optional<double> c0 = {},
               std::optional<double> c_inf = {});
  ~TabulatedFrf() override;
  TabulatedFrf(const TabulatedFrf&) = delete;
  TabulatedFrf& operator=(const TabulatedFrf&) = delete;

  /// H(k) [m/Pa] for k > 0 [rad/m]; throws InvalidArgument for k <= 0, not finite, or an H that
  /// overflows.
  double operator()(double k) const override;
  double c0() const override { return c0_; }        ///< given or estimated [1/Pa]
  double c_inf() const override { return c_inf_; }  ///< given or estimated [1/Pa]
  std::string name() const override { return "table"; }

  bool c0_estimated() const { return c0_estimated_; }
  bool c_inf_estimated() const { return c_inf_estimated_; }
  /// A line for each given limit more than limit_warning_tolerance from the table's end
  /// ("c0 = ... differ by 5 %, ..."; the program prefixes [frf], Python TabulatedFrf).
  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t size() const { return k_.size(); }
  const std::vector<double>& k() const { return k_; }  ///< the table's k [rad/m]
  const std::vector<double>& H() const { return H_; }  ///< the table's H [m/Pa]

 private:
  struct Spline;

  std::vector<double> k_, H_;
  std::vector<double> log_k_, kH_;  // the interpolated data
  double c0_ = 0.0, c_inf_ = 0.0;
  bool c0_estimated_ = false, c_inf_estimated_ = false;
  std::vector<std::string> warnings_;
  std::unique_ptr<const Spline> spline_;
};

}  // namespace coatfft
