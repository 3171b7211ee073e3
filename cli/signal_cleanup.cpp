#include "cli/signal_cleanup.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace coatfft::cli {

namespace {

constexpr int kSlots = 4;
// A run stages up to about 25 outputs (a partial slip with [stress] on a coated body), each with
// its temporary name.
constexpr int kPathsPerSlot = 64;
constexpr std::size_t kPathBytes = 4096;
constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

// Paths as C strings in static storage: the handler may read them at any moment, so a slot is
// filled completely before it is marked in use, and marked free before it is changed.
struct Slot {
  std::atomic<bool> in_use{false};
  int nb_files = 0;
  int nb_folders = 0;
  char paths[kPathsPerSlot][kPathBytes] = {};
};
Slot slots[kSlots];

// What a SIGINT does: end the process (immediate), or, while a StopOnSigint is alive, ask the
// computation to stop (asking), which it records once (asked). Lock-free, so the handler may
// read and change it.
enum SigintMode : int { immediate, asking, asked };
std::atomic<int> sigint_mode{immediate};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void remove_and_reraise(int sig) {
  int expected = asking;
  if (sig == SIGINT && sigint_mode.compare_exchange_strong(expected, asked)) return;
  for (Slot& slot : slots) {
    if (!slot.in_use.load()) continue;
    for (int n = 0; n < slot.nb_files; ++n) ::unlink(slot.paths[n]);
    for (int n = 0; n < slot.nb_folders; ++n) ::rmdir(slot.paths[slot.nb_files + n]);
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_handler_once() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = remove_and_reraise;
    sigemptyset(&action.sa_mask);
    for (int sig : kSignals) sigaddset(&action.sa_mask, sig);
    for (int sig : kSignals) {
      struct sigaction previous {};
      sigaction(sig, nullptr, &previous);
      // A signal the shell told us to ignore (nohup) stays ignored.
      if (previous.sa_handler != SIG_IGN) sigaction(sig, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

sigset_t held_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (int sig : kSignals) sigaddset(&set, sig);
  return set;
}

}  // namespace

RemoveOnSignal::RemoveOnSignal(const std::vector<std::filesystem::path>& files,
                               const std::vector<std::filesystem::path>& folders)
    : slot_(-1) {
  install_handler_once();
  COATFFT_REQUIRE(files.size() + folders.size() <= kPathsPerSlot, "RemoveOnSignal: too many paths");
  for (int s = 0; s < kSlots && slot_ < 0; ++s)
    if (!slots[s].in_use.load()) slot_ = s;
  if (slot_ < 0) throw Error("RemoveOnSignal: no free slot");
  Slot& slot = slots[slot_];
  int n = 0;
  for (const auto* list : {&files, &folders}) {
    for (const auto& path : *list) {
      const std::string text = path.string();
      COATFFT_REQUIRE(text.size() < kPathBytes, "path too long: ", text.substr(0, 80), "...");
      std::memcpy(slot.paths[n++], text.c_str(), text.size() + 1);
    }
  }
  slot.nb_files = static_cast<int>(files.size());
  slot.nb_folders = static_cast<int>(folders.size());
  slot.in_use.store(true);
}

RemoveOnSignal::~RemoveOnSignal() {
  slots[slot_].in_use.store(false);
}

StopOnSigint::StopOnSigint(std::function<void()> on_check)
    : hook_([on_check = std::move(on_check)] {
        if (on_check) on_check();
        return sigint_mode.load() == asked;
      }) {
  install_handler_once();
  sigint_mode.store(asking);
}

StopOnSigint::~StopOnSigint() {
  sigint_mode.store(immediate);
}

void StopOnSigint::finish() {
  int expected = asking;
  if (sigint_mode.compare_exchange_strong(expected, immediate)) return;
  sigint_mode.store(immediate);
  throw Interrupted();
}

void end_by_sigint() {
  ::signal(SIGINT, SIG_DFL);
  ::raise(SIGINT);
  // Only if SIGINT is blocked: the status a shell gives a process that SIGINT ended.
  std::_Exit(128 + SIGINT);
}

HoldSignals::HoldSignals() {
  const sigset_t set = held_signals();
  sigprocmask(SIG_BLOCK, &set, &saved_);
}

HoldSignals::~HoldSignals() {
  sigprocmask(SIG_SETMASK, &saved_, nullptr);
}

}  // namespace coatfft::cli
