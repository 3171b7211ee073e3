#include "bench/child_process.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/detail/timing.hpp"
#include "core/error.hpp"

namespace coatfft::bench {

ChildOutcome run_child(std::vector<std::string> argv) {
  COATFFT_REQUIRE(!argv.empty(), "run_child: no command given");
  if (argv[0].find('/') == std::string::npos) {
    // execv does not search PATH; resolve the name the way a shell would.
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':'))
      if (std::filesystem::exists(dir + "/" + argv[0])) {
        argv[0] = dir + "/" + argv[0];
        break;
      }
  }
  std::vector<char*> cargv;
  for (std::string& s : argv) cargv.push_back(s.data());
  cargv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  COATFFT_REQUIRE(pid >= 0, "run_child: fork failed");
  if (pid == 0) {
    execv(cargv[0], cargv.data());
    std::perror("run_child: execv");
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  const pid_t waited = wait4(pid, &status, 0, &usage);
  COATFFT_REQUIRE(waited == pid, "run_child: wait4 failed for pid ", pid);
  ChildOutcome out;
  out.wall_s = detail::seconds_since(start);
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  out.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  return out;
}

std::string self_executable() {
  return std::filesystem::read_symlink("/proc/self/exe").string();
}

}  // namespace coatfft::bench
