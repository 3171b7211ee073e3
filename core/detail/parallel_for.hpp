#pragma once
// Fork-join loops for the library's coefficient and sampling loops (private: not installed).
// Each call starts its own std::jthreads and runs worker 0 on the calling thread: the loops run
// once per kernel or operator setup and last milliseconds, against tens of microseconds to start
// a thread, so no pool is kept between calls. An exception thrown by a worker (an FRF refusing a
// wavenumber, say) is kept until every worker has joined and then rethrown to the caller; when
// several throw, the one of the lowest worker index.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace coatfft::detail {

/// The number of workers for `n` iterations on `threads` threads: in [1, max(n, 1)].
inline std::ptrdiff_t worker_count(std::ptrdiff_t n, int threads) {
  return std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, n));
}

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
  {
    std::vector<std::jthread> pool;
    pool.reserve(static_cast<std::size_t>(workers - 1));
    for (std::ptrdiff_t w = 1; w < workers; ++w) pool.emplace_back(guarded, w);
    guarded(0);
  }  // the jthreads join here
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// Runs body(i) for every i in [begin, end) on min(threads, end - begin) workers, interleaved
/// (worker w takes begin + w, begin + w + workers, ...): this balances loops whose cost varies
/// smoothly with i (triangular loops, disks, rules that change with distance). The bodies must
/// write disjoint outputs; the result then does not depend on `threads`.
template <class Body>
void parallel_for(std::ptrdiff_t begin, std::ptrdiff_t end, int threads, const Body& body) {
  const std::ptrdiff_t workers = worker_count(end - begin, threads);
  run_workers(workers, [&](std::ptrdiff_t w) {
    for (std::ptrdiff_t i = begin + w; i < end; i += workers) body(i);
  });
}

/// Runs body(w, first, last) on contiguous chunks [first, last) of [begin, end), one per worker
/// w in [0, min(threads, end - begin)), chunk w starting at begin + (end - begin) w / workers: for
/// loops that need per-worker scratch (indexed by w) or memory locality more than balance.
template <class Body>
void parallel_chunks(std::ptrdiff_t begin, std::ptrdiff_t end, int threads, const Body& body) {
  const std::ptrdiff_t n = end - begin;
  const std::ptrdiff_t workers = worker_count(n, threads);
  run_workers(workers, [&](std::ptrdiff_t w) {
    body(w, begin + n * w / workers, begin + n * (w + 1) / workers);
  });
}

}  // namespace coatfft::detail
