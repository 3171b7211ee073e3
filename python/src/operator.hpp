#pragma once
// Operator in Python: a built SurfaceOperator with its report. apply() runs without the GIL, so
// one operator is guarded by a mutex: SurfaceOperator::apply is not safe from two threads at
// once, and two Python threads may call it together. The pressure and the displacement pass
// through two fields the operator keeps: an application then allocates nothing but its result
// (none with `out`), since fresh grid-sized memory costs its page faults on every call.
#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>
#include <string_view>

#include "arrays.hpp"
#include "convolution/operators/make_operator.hpp"
#include "frf/frf.hpp"

namespace coatfft::python {

class Operator {
 public:
  Operator(BuiltOperator built, pybind11::dict report, int threads,
           std::shared_ptr<const Frf> body_response)
      : built_(std::move(built)),
        report_(std::move(report)),
        threads_(threads),
        body_response_(std::move(body_response)) {}

  const Grid& grid() const { return built_.op->grid(); }
  const pybind11::dict& report() const { return report_; }
  /// The threads it was built with, which a contact solve on it uses too (the solver's
  /// preconditioner and element-wise passes), as `coatfft run` does.
  int threads() const { return threads_; }
  std::string_view method() const { return to_string(built_.report.method); }
  /// Whether the displacement's level is known: not for an FRF pipeline built with
  /// g0 = "omitted", whose displacements carry an unknown constant offset.
  bool has_g0() const { return !built_.report.g0 || built_.report.g0->method != G0Method::omitted; }
  /// The FRF of the body the operator was made for, as the caller gave it (before any reduction
  /// of the automatic choice): what a solve that needs the body again compares its body with.
  const Frf& body_response() const { return *body_response_; }
  /// u [m] of the pressure p [Pa], both (ny, nx); into `out` when it is an array (output_array).
  pybind11::array_t<double> apply(const DoubleArray& pressure, const pybind11::object& out);

  /// The operator, for a caller that holds lock() and has released the GIL.
  SurfaceOperator& op() { return *built_.op; }
  std::unique_lock<std::mutex> lock() { return std::unique_lock(mutex_); }

 private:
  BuiltOperator built_;
  pybind11::dict report_;
  int threads_;
  std::shared_ptr<const Frf> body_response_;
  std::mutex mutex_;
  Field pressure_;      // apply()'s input, copied from numpy
  Field displacement_;  // and its output, before it is copied out
};

}  // namespace coatfft::python
