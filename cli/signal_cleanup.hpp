#pragma once
// Temporary files removed when the run is interrupted. A SIGINT, SIGTERM or SIGHUP ends the
// program without unwinding the stack, so destructors cannot clean up; the handler installed here
// unlinks the registered files and folders (async-signal-safe unlink/rmdir on paths prepared in
// advance) and then ends the process with the signal's default action.
//
// While a computation can stop by itself (StopOnSigint), the first SIGINT only asks it to: the
// library sees the request at its next check (core/interrupt.hpp), the stack unwinds, the
// destructors remove the staged output, and main() reports and ends the process by SIGINT
// (end_by_sigint). A second SIGINT, or SIGTERM or SIGHUP, still ends the process at once.
#include <signal.h>

#include <filesystem>
#include <functional>
#include <vector>

#include "core/interrupt.hpp"

namespace coatfft::cli {

/// While alive, `files` are unlinked and then `folders` removed (when empty) if the process
/// receives SIGINT, SIGTERM or SIGHUP. Registrations nest; at most a handful are alive at once.
class RemoveOnSignal {
 public:
  RemoveOnSignal(const std::vector<std::filesystem::path>& files,
                 const std::vector<std::filesystem::path>& folders);
  ~RemoveOnSignal();
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

 private:
  int slot_;
};

/// While alive, the first SIGINT asks the computation of this thread to stop: its checks
/// (core/interrupt.hpp) throw coatfft::Interrupted. Each check, at most every 50 ms, also calls
/// `on_check` (the progress line of a long stage).
class StopOnSigint {
 public:
  explicit StopOnSigint(std::function<void()> on_check = {});
  ~StopOnSigint();
  StopOnSigint(const StopOnSigint&) = delete;
  StopOnSigint& operator=(const StopOnSigint&) = delete;

  /// SIGINT ends the process at once again; throws Interrupted if one came since the last check.
  void finish();

 private:
  ScopedInterruptHook hook_;
};

/// Ends the process as an uncaught SIGINT does (the shell sees status 130), for main() once an
/// interrupted computation has unwound.
[[noreturn]] void end_by_sigint();

/// While alive, SIGINT, SIGTERM and SIGHUP are held back (delivered when it ends): a sequence of
/// renames that must not stop half-way runs under one.
class HoldSignals {
 public:
  HoldSignals();
  ~HoldSignals();
  HoldSignals(const HoldSignals&) = delete;
  HoldSignals& operator=(const HoldSignals&) = delete;

 private:
  sigset_t saved_;
};

}  // namespace coatfft::cli
