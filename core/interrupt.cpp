#include "core/interrupt.hpp"

#include <atomic>
#include <memory>
#include <thread>
#include <utility>

namespace coatfft {

namespace detail {

struct InterruptState {
  std::function<bool()> hook;
  std::chrono::steady_clock::duration interval;
  std::thread::id owner = std::this_thread::get_id();
  std::atomic<bool> stop{false};
  // Read and written by the owner only. A call shorter than one interval never asks.
  std::chrono::steady_clock::time_point last_asked;
};

namespace {

thread_local InterruptState* current = nullptr;

bool ask(InterruptState& state) {
  if (state.stop.load(std::memory_order_relaxed)) return true;
  if (std::this_thread::get_id() != state.owner) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - state.last_asked < state.interval) return false;
  state.last_asked = now;
  if (!state.hook()) return false;
  state.stop.store(true, std::memory_order_relaxed);
  return true;
}

}  // namespace

bool poll_interrupt() {
  return current != nullptr && ask(*current);
}

InterruptState* current_interrupt_state() {
  return current;
}

SharedInterruptState::SharedInterruptState(InterruptState* state) : previous_(current) {
  current = state;
}

SharedInterruptState::~SharedInterruptState() {
  current = previous_;
}

}  // namespace detail

ScopedInterruptHook::ScopedInterruptHook(std::function<bool()> hook,
                                         std::chrono::milliseconds interval)
    : state_(std::make_unique<detail::InterruptState>()), previous_(detail::current) {
  state_->hook = std::move(hook);
  state_->interval = interval;
  state_->last_asked = std::chrono::steady_clock::now();
  detail::current = state_.get();
}

ScopedInterruptHook::~ScopedInterruptHook() {
  detail::current = previous_;
}

bool ScopedInterruptHook::interrupted() const {
  return state_->stop.load(std::memory_order_relaxed);
}

void check_interrupt() {
  if (detail::poll_interrupt()) throw Interrupted();
}

}  // namespace coatfft
