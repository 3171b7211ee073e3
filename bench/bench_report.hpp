#pragma once
// What every benchmark writes around its numbers: the `# key = value` header that says which
// machine, compiler, flags and FFTW produced them (timings mean nothing without it), peak
// resident memory, and the write of the result file. (Timing and medians: core/detail/timing.hpp;
// child processes: bench/child_process.hpp.)

#include <ostream>
#include <string>

#include "core/detail/write_text_file.hpp"

namespace coatfft::bench {

/// `# cpu`, `# hardware_threads`, `# compiler`, `# flags`, `# fftw` and `# date` lines.
void write_machine_header(std::ostream& os);

/// Peak resident set size of this process so far [MiB] (getrusage; ru_maxrss is KiB on Linux).
double peak_rss_mb();

/// Writes text to path (creating its folder), or throws coatfft::Error naming the path.
using detail::write_text_file;

}  // namespace coatfft::bench
