#pragma once
// Writing a whole result file (private: not installed): what the table programs and the
// benchmarks do with their Markdown and CSV output.
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace coatfft::detail {

/// Writes `text` to `path`, creating its folder, or throws coatfft::Error naming the path.
inline void write_text_file(const std::string& path, const std::string& text) {
  const std::filesystem::path p(path);
  std::error_code ec;  // reported below as "cannot write PATH", not as a filesystem_error
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
  std::ofstream out(p);
  out << text;
  out.close();
  COATFFT_REQUIRE(out.good(), "cannot write '", path, "'");
}

}  // namespace coatfft::detail
