#pragma once
// Number formatting for the validation tables (Markdown written by the *_table programs).
#include <cstdio>
#include <string>

namespace coatfft::tables {

/// `value` printed with the printf conversion `format` ("%.3e", "%+.1e", ...; at most 63
/// characters), for table cells where iostream manipulators would be verbose.
inline std::string format_number(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace coatfft::tables
