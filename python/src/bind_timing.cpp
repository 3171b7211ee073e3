// coatfft._coatfft.timing: the C++ side of bench/bench_python.py, which measures what a call from
// Python adds. Each function times the library's own loop, in C++, on the same inputs the Python
// call gets, and returns the median of `repeat` timings [s].
#include <chrono>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "operator.hpp"
#include "without_gil.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

void check_repeat(int repeat) {
  COATFFT_REQUIRE(repeat >= 1, "repeat = ", repeat, " must be >= 1");
}

// One SurfaceOperator::apply from C++, into a field allocated once: the library's own timing.
double apply_seconds(Operator& op, const DoubleArray& pressure, int repeat) {
  check_repeat(repeat);
  const Field p = field_from_array(pressure, op.grid(), "pressure");
  Field u(p.rows(), p.cols());
  return without_gil([&] {
    const auto guard = op.lock();
    return detail::time_applications(op.op(), p, u, repeat);
  });
}

// The plain C++ loop of H(k) calls, one virtual call per wavenumber.
double frf_loop_seconds(py::handle body, const DoubleArray& k, int repeat) {
  const std::shared_ptr<const Frf> frf = body_from_object(body).response();
  std::vector<double> h(static_cast<std::size_t>(k.size()));
  const double* ks = k.data();
  check_repeat(repeat);
  std::vector<double> seconds;
  return without_gil([&] {
    for (int r = 0; r < repeat; ++r) {
      check_interrupt();
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < h.size(); ++i) h[i] = (*frf)(ks[i]);
      seconds.push_back(detail::seconds_since(start));
    }
    return detail::median(std::move(seconds));
  });
}

}  // namespace

void bind_timing(py::module_& m) {
  py::module_ timing = m.def_submodule("timing", "C++ timings for bench/bench_python.py");
  timing.def("apply_seconds", &apply_seconds, "op"_a, "p"_a, "repeat"_a,
             "Median time [s] of one apply() called from C++.");
  timing.def("frf_loop_seconds", &frf_loop_seconds, "body"_a, "k"_a, "repeat"_a,
             "Median time [s] of a C++ loop of H(k) calls over the array k.");
}

}  // namespace coatfft::python
