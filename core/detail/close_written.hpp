#pragma once
// The end of writing a file (private: not installed). A stream buffers what is written: a full
// disk or a file-size limit shows only when the buffer is flushed, at the latest by close(), so a
// file is known written only once it is closed and the stream is still good.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace coatfft::detail {

/// Closes `out` and throws InvalidArgument ("failed writing WHAT PATH: reason") when any write to
/// it or the close failed.
inline void close_written(std::ofstream& out, const std::filesystem::path& path,
                          std::string_view what = {}) {
  const bool written = !out.fail();
  errno = 0;
  out.close();
  if (!out.fail()) return;
  // The reason is known when the close (its flush) failed; an earlier write's errno may be gone.
  const std::string reason =
      written && errno != 0 ? concat(": ", std::strerror(errno)) : std::string();
  throw InvalidArgument(
      concat("failed writing ", what, what.empty() ? "" : " ", path.string(), reason));
}

}  // namespace coatfft::detail
