#pragma once
// Stopping a long call on request (Ctrl-C in Python or on the command line). The library runs
// without Python's GIL and installs no signal handler of its own, so it cannot see a signal; it
// asks instead. A caller installs a hook, a function that says whether to stop, for the duration
// of a call (ScopedInterruptHook); the long loops of the library (kernel and operator set-up,
// stresses, contact iterations, repeated applications) call check_interrupt() between steps,
// which calls the hook at most once per interval and throws Interrupted when it says stop.
//
// The hook belongs to the thread that installed it: only that thread calls it, so a hook may
// touch state of that thread (Python's signal check runs on the main thread only; the CLI's
// progress line is written by the computing thread). The library's worker threads share the
// answer through an atomic flag. An interrupted call unwinds like any exception: the objects it
// was given stay usable (an operator interrupted in an application gives the same result when
// applied again), and what it was building is released.
#include <chrono>
#include <exception>
#include <functional>
#include <memory>

namespace coatfft {

/// Thrown by a call that its interrupt hook stopped. Not a coatfft::Error: code that turns
/// errors into reports or fallbacks must not swallow a request to stop.
class Interrupted : public std::exception {
 public:
  const char* what() const noexcept override { return "interrupted"; }
};

namespace detail {
struct InterruptState;
}

/// While alive, check_interrupt() on this thread (and on the library's workers it starts) calls
/// `hook` at most once per `interval` and throws Interrupted once it returns true. Hooks nest:
/// the innermost one is asked, and the previous one is back when it ends.
class ScopedInterruptHook {
 public:
  static constexpr std::chrono::milliseconds default_interval{50};

  explicit ScopedInterruptHook(std::function<bool()> hook,
                               std::chrono::milliseconds interval = default_interval);
  ~ScopedInterruptHook();
  ScopedInterruptHook(const ScopedInterruptHook&) = delete;
  ScopedInterruptHook& operator=(const ScopedInterruptHook&) = delete;

  /// Whether the hook has said stop.
  bool interrupted() const;

 private:
  std::unique_ptr<detail::InterruptState> state_;
  detail::InterruptState* previous_;
};

/// Throws Interrupted when the hook of this thread says stop (or has said so); without a hook,
/// does nothing. Cheap enough for a loop whose steps take microseconds: the clock is read on the
/// hook's own thread only, a flag elsewhere.
void check_interrupt();

namespace detail {

/// check_interrupt() without the throw: whether to stop.
bool poll_interrupt();

/// The hook state of this thread (null without a hook), for handing to worker threads.
InterruptState* current_interrupt_state();

/// While alive, this (worker) thread shares `state`: its check_interrupt() reads the state's
/// flag, and never calls the hook, which belongs to the thread that installed it.
class SharedInterruptState {
 public:
  explicit SharedInterruptState(InterruptState* state);
  ~SharedInterruptState();
  SharedInterruptState(const SharedInterruptState&) = delete;
  SharedInterruptState& operator=(const SharedInterruptState&) = delete;

 private:
  InterruptState* previous_;
};

}  // namespace detail

}  // namespace coatfft
