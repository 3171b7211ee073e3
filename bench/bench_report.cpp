#include "bench/bench_report.hpp"

#include <fftw3.h>
#include <sys/resource.h>

#include <ctime>
#include <fstream>
#include <thread>

#include "core/error.hpp"

#ifndef COATFFT_BENCH_FLAGS
#define COATFFT_BENCH_FLAGS "unknown"
#endif

namespace coatfft::bench {
namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string compiler_id() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

void write_machine_header(std::ostream& os) {
  os << "# date = " << utc_now() << "\n"
     << "# cpu = " << cpu_model() << "\n"
     << "# hardware_threads = " << std::thread::hardware_concurrency() << "\n"
     << "# compiler = " << compiler_id() << "\n"
     << "# flags = " << COATFFT_BENCH_FLAGS << "\n"
     << "# fftw = " << fftw_version << "\n";
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace coatfft::bench
