#include "frf/tabulated_frf.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/detail/gsl_quadrature.hpp"
#include "core/error.hpp"

namespace coatfft {

// The GSL interpolant of k H against ln k. gsl_interp holds only the spline's coefficients; the
// data arrays are passed to each evaluation, and no gsl_interp_accel is used, so concurrent
// evaluations share nothing mutable.
struct TabulatedFrf::Spline {
  struct Deleter {
    void operator()(gsl_interp* p) const { gsl_interp_free(p); }
  };
  std::unique_ptr<gsl_interp, Deleter> interp;
};

namespace {

void check_rows(const std::vector<double>& k, const std::vector<double>& H) {
  COATFFT_REQUIRE(k.size() == H.size(), "TabulatedFrf: ", k.size(), " values of k but ", H.size(),
                  " of H");
  COATFFT_REQUIRE(k.size() >= TabulatedFrf::min_points, "TabulatedFrf: ", k.size(),
                  " rows, but a table needs at least ", TabulatedFrf::min_points);
  for (std::size_t i = 0; i < k.size(); ++i) {
    COATFFT_REQUIRE(std::isfinite(k[i]) && k[i] > 0, "TabulatedFrf: row ", i, ": k = ", k[i],
                    " rad/m, but it must be finite and > 0");
    COATFFT_REQUIRE(std::isfinite(H[i]) && H[i] > 0, "TabulatedFrf: row ", i, ": H = ", H[i],
                    " m/Pa, but it must be finite and > 0");
    COATFFT_REQUIRE(i == 0 || k[i] > k[i - 1], "TabulatedFrf: row ", i, ": k = ", k[i],
                    " rad/m, but k must be strictly ascending (row ", i - 1, ": k = ", k[i - 1],
                    ")");
    COATFFT_REQUIRE(i == 0 || std::log(k[i]) > std::log(k[i - 1]), "TabulatedFrf: row ", i,
                    ": k = ", k[i], " rad/m is too close to row ", i - 1, "'s k = ", k[i - 1],
                    " (their logarithms coincide)");
  }
}

void check_limit(const char* name, std::optional<double> value) {
  COATFFT_REQUIRE(!value || (std::isfinite(*value) && *value > 0), "TabulatedFrf: ", name, " = ",
                  value.value_or(0), " 1/Pa, but it must be finite and > 0");
}

// The end value of k H at one end of the table (front: small k, else large k), refused unless k H
// varies by at most flatness_tolerance over the decade of k at that end.
double end_value(const std::vector<double>& k, const std::vector<double>& kH, bool front) {
  const std::size_t n = k.size();
  const std::size_t end = front ? 0 : n - 1;
  double variation = 0.0;
  std::size_t far = end;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = front ? j : n - 1 - j;
    if (front ? k[i] > 10.0 * k[end] : k[i] < 0.1 * k[end]) break;
    const double v = std::abs(kH[i] - kH[end]) / kH[end];
    if (v > variation) {
      variation = v;
      far = i;
    }
  }
  COATFFT_REQUIRE(variation <= TabulatedFrf::flatness_tolerance, "TabulatedFrf: k H varies by ",
                  variation, " (relative) between k = ", k[end], " and k = ", k[far],
                  " rad/m, more than ", TabulatedFrf::flatness_tolerance,
                  ": the table does not reach the ", front ? "small" : "large",
                  "-k limit; extend it, or give ", front ? "c0" : "c_inf", " (",
                  front ? "2/E*_substrate" : "2/E*_top", ")");
  return kH[end];
}

// `x` > 0 to three significant digits, for ratios in messages ("a factor 1e+08", not 99999999.99).
double three_digits(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2.0);
  return std::round(x / unit) * unit;
}

// A given limit against the table's k H at that end (front: c0 at the smallest k, else c_inf at
// the largest): refused beyond limit_refusal_factor either way, a warning returned beyond
// limit_warning_tolerance, else an empty string.
std::string check_given_limit(const std::vector<double>& k, const std::vector<double>& kH,
                              bool front, double given) {
  const std::size_t end = front ? 0 : k.size() - 1;
  const char* name = front ? "c0" : "c_inf";
  const double ratio = std::max(given / kH[end], kH[end] / given);
  const auto describe = [&](double value) {
    return detail::concat(name, " = ", value, " 1/Pa and the table's k H = ", kH[end],
                          " 1/Pa at its ", front ? "smallest" : "largest", " k = ", k[end],
                          " rad/m");
  };
  COATFFT_REQUIRE(ratio <= TabulatedFrf::limit_refusal_factor, "TabulatedFrf: ", describe(given),
                  " differ by a factor ", three_digits(ratio), ", more than ",
                  TabulatedFrf::limit_refusal_factor, ": they contradict each other (check ", name,
                  ", ", front ? "2/E*_substrate" : "2/E*_top",
                  ", and the table's units), or extend the table towards the limit");
  if (std::abs(given / kH[end] - 1.0) <= TabulatedFrf::limit_warning_tolerance) return {};
  return detail::concat(
      describe(given), " differ by ", three_digits(std::abs(given / kH[end] - 1.0) * 100.0),
      " %, more than ", TabulatedFrf::limit_warning_tolerance * 100.0,
      " %: beyond the table k H is ", front ? "continued linearly in k" : "carried exponentially",
      " to the given limit");
}

// The smallest value of the spline piece on [x[i], x[i+1]]: at an end, or where its derivative, a
// quadratic in t = x - x[i] from the first and second derivatives GSL gives, vanishes.
double piece_minimum(const gsl_interp* interp, const double* x, const double* y, std::size_t i) {
  const double h = x[i + 1] - x[i];
  const double d1 = gsl_interp_eval_deriv(interp, x, y, x[i], nullptr);
  const double s0 = gsl_interp_eval_deriv2(interp, x, y, x[i], nullptr);
  const double s1 = gsl_interp_eval_deriv2(interp, x, y, x[i + 1], nullptr);
  // S'(t) = d1 + s0 t + q t^2.
  const double q = (s1 - s0) / (2.0 * h);
  double roots[2] = {-1.0, -1.0};
  if (q == 0.0) {
    if (s0 != 0.0) roots[0] = -d1 / s0;
  } else {
    const double disc = s0 * s0 - 4.0 * q * d1;
    if (disc >= 0.0) {
      roots[0] = (-s0 - std::sqrt(disc)) / (2.0 * q);
      roots[1] = (-s0 + std::sqrt(disc)) / (2.0 * q);
    }
  }
  double lowest = std::min(y[i], y[i + 1]);
  for (const double t : roots)
    if (t > 0.0 && t < h)
      lowest = std::min(lowest, gsl_interp_eval(interp, x, y, x[i] + t, nullptr));
  return lowest;
}

}  // namespace

TabulatedFrf::TabulatedFrf(std::vector<double> k, std::vector<double> H, std::optional<double> c0,
                           std::optional<double> c_inf)
    : k_(std::move(k)), H_(std::move(H)) {
  check_rows(k_, H_);
  check_limit("c0", c0);
  check_limit("c_inf", c_inf);
  for (std::size_t i = 0; i < k_.size(); ++i) {
    log_k_.push_back(std::log(k_[i]));
    kH_.push_back(k_[i] * H_[i]);
    COATFFT_REQUIRE(std::isfinite(kH_[i]) && kH_[i] > 0, "TabulatedFrf: row ", i, ": k H = ", k_[i],
                    " * ", H_[i], " is out of the range of double");
  }
  c0_estimated_ = !c0;
  c_inf_estimated_ = !c_inf;
  c0_ = c0 ? *c0 : end_value(k_, kH_, true);
  c_inf_ = c_inf ? *c_inf : end_value(k_, kH_, false);
  for (const bool front : {true, false}) {
    if (!(front ? c0 : c_inf)) continue;
    std::string warning = check_given_limit(k_, kH_, front, front ? c0_ : c_inf_);
    if (!warning.empty()) warnings_.push_back(std::move(warning));
  }

  auto spline = std::make_unique<Spline>();
  spline->interp.reset(gsl_interp_alloc(gsl_interp_cspline, k_.size()));
  COATFFT_REQUIRE(spline->interp != nullptr, "TabulatedFrf: cannot allocate the interpolant");
  const detail::GslHandlerOff off;
  const int status =
      gsl_interp_init(spline->interp.get(), log_k_.data(), kH_.data(), log_k_.size());
  COATFFT_REQUIRE(status == GSL_SUCCESS, "TabulatedFrf: gsl_interp_init: ", gsl_strerror(status));
  // A spline through positive values can still dip below zero between them where the table is
  // coarse against a sharp feature; H must stay > 0 (Frf's contract).
  for (std::size_t i = 0; i + 1 < k_.size(); ++i) {
    const double lowest = piece_minimum(spline->interp.get(), log_k_.data(), kH_.data(), i);
    COATFFT_REQUIRE(lowest > 0, "TabulatedFrf: between row ", i, " (k = ", k_[i], ") and row ",
                    i + 1, " (k = ", k_[i + 1], " rad/m) the interpolated k H reaches ", lowest,
                    ", but H must stay > 0: the table is too coarse there; add rows");
  }
  spline_ = std::move(spline);
}

TabulatedFrf::~TabulatedFrf() = default;

double TabulatedFrf::operator()(double k) const {
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, "TabulatedFrf: k = ", k,
                  " rad/m, but the wavenumber must be finite and > 0");
  const double k_min = k_.front();
  const double k_max = k_.back();
  double kH = 0.0;
  if (k <= k_min) {
    kH = c0_ + (kH_.front() - c0_) * (k / k_min);
  } else if (k >= k_max) {
    kH = c_inf_ + (kH_.back() - c_inf_) * std::exp(1.0 - k / k_max);
  } else {
    // ln is monotone, so ln k lies in [ln k_min, ln k_max]: GSL's range check cannot fail.
    const double x = std::clamp(std::log(k), log_k_.front(), log_k_.back());
    kH = gsl_interp_eval(spline_->interp.get(), log_k_.data(), kH_.data(), x, nullptr);
  }
  const double h = kH / k;
  COATFFT_REQUIRE(std::isfinite(h), "TabulatedFrf: H(k = ", k, " rad/m) overflows");
  return h;
}

}  // namespace coatfft
