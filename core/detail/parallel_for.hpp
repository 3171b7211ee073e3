#pragma once
// Fork-join loops for the library's coefficient and sampling loops (private: not installed).
// Each call starts its own std::jthreads and runs worker 0 on the calling thread: the loops run
// once per kernel or operator setup and last milliseconds, against tens of microseconds to start
// a thread, so no pool is kept between calls. An exception thrown by a worker (an FRF refusing a
// wavenumber, say) is kept until every worker has joined and then rethrown to the caller; when
// several throw, the one of the lowest worker index.
//
// The loops can be interrupted (core/interrupt.hpp): the workers share the calling thread's
// interrupt hook, parallel_for checks it before each iteration, and the calling thread, once its
// own share is done, keeps asking its hook while it waits for the others, so that a request to
// stop reaches a worker still busy with a long share.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/interrupt.hpp"

namespace coatfft::detail {

/// The number of workers for `n` iterations on `threads` threads: in [1, max(n, 1)].
inline std::ptrdiff_t worker_count(std::ptrdiff_t n, int threads) {
  return std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, n));
}

/// The workers still running, and the calling thread's wait for them.
class RunningWorkers {
 public:
  explicit RunningWorkers(std::ptrdiff_t count) : count_(count) {}
  void done() {
    {
      const std::lock_guard lock(mutex_);
      --count_;
    }
    changed_.notify_one();
  }
  /// Waits until every worker is done, asking the interrupt hook every few milliseconds (its
  /// answer reaches the workers through the shared flag; the jthreads are joined after this).
  void wait_asking_hook() {
    std::unique_lock lock(mutex_);
    while (count_ > 0) {
      changed_.wait_for(lock, std::chrono::milliseconds(10));
      lock.unlock();
      poll_interrupt();
      lock.lock();
    }
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::ptrdiff_t count_;
};

/// Runs work(w) for every w in [0, workers), w = 0 on the calling thread; with one worker, inline.
template <class Work>
void run_workers(std::ptrdiff_t workers, const Work& work) {
  if (workers <= 1) {
    work(std::ptrdiff_t{0});
    return;
  }
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
  const auto guarded = [&](std::ptrdiff_t w) {
    try {
      work(w);
    } catch (...) {
      errors[static_cast<std::size_t>(w)] = std::current_exception();
    }
  };
  InterruptState* const interrupt = current_interrupt_state();
  RunningWorkers running(workers - 1);
  {
    std::vector<std::jthread> pool;
    pool.reserve(static_cast<std::size_t>(workers - 1));
    for (std::ptrdiff_t w = 1; w < workers; ++w)
      pool.emplace_back([&, w] {
        const SharedInterruptState shared(interrupt);
        guarded(w);
        running.done();
      });
    guarded(0);
    if (interrupt) running.wait_asking_hook();
  }  // the jthreads join here
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// Runs body(i) for every i in [begin, end) on min(threads, end - begin) workers, interleaved
/// (worker w takes begin + w, begin + w + workers, ...): this balances loops whose cost varies
/// smoothly with i (triangular loops, disks, rules that change with distance). The bodies must
/// write disjoint outputs; the result then does not depend on `threads`. Throws Interrupted
/// (core/interrupt.hpp) between iterations when asked to stop.
template <class Body>
void parallel_for(std::ptrdiff_t begin, std::ptrdiff_t end, int threads, const Body& body) {
  const std::ptrdiff_t workers = worker_count(end - begin, threads);
  run_workers(workers, [&](std::ptrdiff_t w) {
    for (std::ptrdiff_t i = begin + w; i < end; i += workers) {
      check_interrupt();
      body(i);
    }
  });
}

/// Runs body(w, first, last) on contiguous chunks [first, last) of [begin, end), one per worker
/// w in [0, min(threads, end - begin)), chunk w starting at begin + (end - begin) w / workers: for
/// loops that need per-worker scratch (indexed by w) or memory locality more than balance. The
/// bodies check for interrupts themselves where their chunks are long.
template <class Body>
void parallel_chunks(std::ptrdiff_t begin, std::ptrdiff_t end, int threads, const Body& body) {
  const std::ptrdiff_t n = end - begin;
  const std::ptrdiff_t workers = worker_count(n, threads);
  run_workers(workers, [&](std::ptrdiff_t w) {
    body(w, begin + n * w / workers, begin + n * (w + 1) / workers);
  });
}

}  // namespace coatfft::detail
