#pragma once
// Temporary files removed when the run is interrupted. A SIGINT, SIGTERM or SIGHUP ends the
// program without unwinding the stack, so destructors cannot clean up; the handler installed here
// unlinks the registered files and folders (async-signal-safe unlink/rmdir on paths prepared in
// advance) and then ends the process with the signal's default action.
#include <signal.h>

#include <filesystem>
#include <vector>

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
