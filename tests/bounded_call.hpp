#pragma once
// A reader's call on a crafted file (a declaration bomb) run in a child process under a bound of
// address space and time, so that a reader that allocates what the file declares ends in
// std::bad_alloc or SIGALRM in the child instead of taking the test machine's memory; the parent
// gets what the call threw and the child's peak resident memory (wait4). Under AddressSanitizer,
// which reserves terabytes of shadow, only the time bound and the measured peak apply.
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <exception>
#include <fstream>
#include <functional>
#include <string>

#include "tests/address_sanitized.hpp"

namespace coatfft_test {

struct BoundedCall {
  bool returned = false;    ///< the child ended normally (no signal, no time-out)
  std::string error;        ///< what the call threw ("" if it returned)
  double peak_rss_mib = 0;  ///< the child's peak resident memory
  double seconds = 0;       ///< wall time of the child
};

/// Runs `call` in a child whose address space may grow by `extra_bytes` beyond the parent's and
/// that is killed after `seconds`.
inline BoundedCall run_bounded(const std::function<void()>& call, std::size_t extra_bytes,
                               unsigned seconds) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return {};
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipe_ends[0]);
    malloc_trim(0);  // the free memory at the top of the heap given back: the bound counts it
    std::size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;  // the address space now [pages]
    const rlim_t limit = pages * static_cast<rlim_t>(sysconf(_SC_PAGESIZE)) + extra_bytes;
    const struct rlimit bound { limit, limit };
    if (!address_sanitized()) setrlimit(RLIMIT_AS, &bound);
    alarm(seconds);
    std::string error;
    try {
      call();
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (write(pipe_ends[1], error.data(), error.size()) < 0) _exit(3);
    _exit(0);
  }
  close(pipe_ends[1]);
  BoundedCall result;
  char chunk[512];
  for (ssize_t n; (n = read(pipe_ends[0], chunk, sizeof chunk)) > 0;) result.error.append(chunk, n);
  close(pipe_ends[0]);
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.returned = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  result.peak_rss_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return result;
}

}  // namespace coatfft_test
