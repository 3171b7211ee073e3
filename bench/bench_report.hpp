#pragma once
// What every benchmark writes around its numbers: the `# key = value` header that says which
// machine, compiler, flags and FFTW produced them (timings mean nothing without it), medians,
// peak resident memory, and the write of the result file.

#include <ostream>
#include <string>
#include <vector>

namespace coatfft::bench {

/// `# cpu`, `# hardware_threads`, `# compiler`, `# flags`, `# fftw` and `# date` lines.
void write_machine_header(std::ostream& os);

/// Peak resident set size of this process so far [MiB] (getrusage; ru_maxrss is KiB on Linux).
double peak_rss_mb();

/// Median of v (the upper one for an even count; 0 for an empty v): robust to the outliers a
/// shared machine produces.
double median(std::vector<double> v);

/// "512,1024" -> {512, 1024}; throws coatfft::Error naming the item that is not an integer.
std::vector<int> parse_int_list(const std::string& text);

/// Writes text to path (creating its folder), or throws coatfft::Error naming the path.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace coatfft::bench
