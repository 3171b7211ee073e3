#pragma once
// Long calls that Ctrl-C can stop. The library runs without the GIL, and Python runs a signal's
// handler only when its main thread gets back to the interpreter: a SIGINT during a call of
// minutes would otherwise raise KeyboardInterrupt only once the call had ended. Each call that
// releases the GIL therefore installs an interrupt hook (core/interrupt.hpp) that, at most every
// 50 ms, takes the GIL back for a moment and runs the handlers (PyErr_CheckSignals). When one
// raises, the hook keeps that exception and says stop; the library throws Interrupted at its next
// check, which unwinds the call, and the kept exception (KeyboardInterrupt for Ctrl-C, or
// whatever a handler of the user's raised) is raised in Python in its place.
#include <pybind11/pybind11.h>

#include <optional>
#include <utility>

#include "core/interrupt.hpp"

namespace coatfft::python {

/// work() without the GIL, stopped by a signal whose Python handler raises.
template <class Work>
auto without_gil(Work&& work) -> decltype(work()) {
  // Fetched and released with the GIL held: made in the hook, dropped or thrown below.
  std::optional<pybind11::error_already_set> raised;
  try {
    const pybind11::gil_scoped_release release;
    const ScopedInterruptHook hook([&raised] {
      const pybind11::gil_scoped_acquire gil;
      // Only the main thread runs handlers: elsewhere this returns 0 at once.
      if (PyErr_CheckSignals() == 0) return false;
      raised.emplace();  // takes the exception out of the interpreter
      return true;
    });
    return std::forward<Work>(work)();
  } catch (const Interrupted&) {
    if (raised) throw pybind11::error_already_set(std::move(*raised));
    throw;
  }
}

}  // namespace coatfft::python
