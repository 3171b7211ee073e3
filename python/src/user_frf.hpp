#pragma once
// An FRF given by a Python function of a numpy array of wavenumbers: UserFrf in Python. The
// library's pipelines ask for H in batches (Frf::evaluate: a lattice column, a table), so the
// function is called once per batch; adaptive quadratures (g(0), the Hankel reference, error
// predictions) ask for one wavenumber at a time, a batch of one.
#include <pybind11/pybind11.h>

#include <atomic>
#include <span>
#include <string>

#include "frf/frf.hpp"

namespace coatfft::python {

class UserFrf final : public Frf {
 public:
  /// function: H(k) [m/Pa] for a 1-D float64 array of k [rad/m], returning an array of the same
  /// shape; c0, c_inf [1/Pa]: the limits of k H(k) at k -> 0 and k -> inf, finite and > 0.
  UserFrf(pybind11::function function, double c0, double c_inf);

  double operator()(double k) const override;
  /// Calls the function with the GIL held (from any thread: the library's workers too). The
  /// function's own exceptions propagate unchanged; a result that is not numeric (None,
  /// strings, complex) raises TypeError, one of the wrong shape or with a value not finite and
  /// > 0 InvalidArgument.
  void evaluate(std::span<const double> k, std::span<double> h) const override;
  double c0() const override { return c0_; }
  double c_inf() const override { return c_inf_; }
  std::string name() const override { return "user"; }

  const pybind11::function& function() const { return function_; }
  /// How many times the function was called (batches), for tests and reports.
  long calls() const { return calls_.load(); }

 private:
  pybind11::function function_;
  double c0_;
  double c_inf_;
  mutable std::atomic<long> calls_{0};
};

}  // namespace coatfft::python
