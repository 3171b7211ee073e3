// coatfft._coatfft.timing: the C++ side of bench/bench_python.py, which measures what a call from
// Python adds. Each function times the library's own loop, in C++, on the same inputs the Python
// call gets, and returns the median of `repeat` timings [s].
#include <algorithm>
#include <chrono>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bodies.hpp"
#include "core/error.hpp"
#include "operator.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace coatfft::python {

namespace {

template <typename Work>
double median_seconds(int repeat, Work&& work) {
  COATFFT_REQUIRE(repeat >= 1, "repeat = ", repeat, " must be >= 1");
  std::vector<double> seconds;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + repeat / 2, seconds.end());
  return seconds[static_cast<std::size_t>(repeat / 2)];
}

// One SurfaceOperator::apply from C++, into a field allocated once.
double apply_seconds(Operator& op, const DoubleArray& pressure, int repeat) {
  const Field p = field_from_array(pressure, op.grid(), "pressure");
  Field u(p.rows(), p.cols());
  py::gil_scoped_release release;
  const auto guard = op.lock();
  return median_seconds(repeat, [&] { op.op().apply(p, u); });
}

// The plain C++ loop of H(k) calls, one virtual call per wavenumber.
double frf_loop_seconds(py::handle body, const DoubleArray& k, int repeat) {
  const std::shared_ptr<const Frf> frf = body_from_object(body).response();
  std::vector<double> h(static_cast<std::size_t>(k.size()));
  const double* ks = k.data();
  py::gil_scoped_release release;
  return median_seconds(repeat, [&] {
    for (std::size_t i = 0; i < h.size(); ++i) h[i] = (*frf)(ks[i]);
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
