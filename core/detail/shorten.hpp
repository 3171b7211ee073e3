#pragma once
// Values echoed in error messages are shortened, so that a megabyte-long material name or a
// corrupt file header still gives a one-line message.
#include <string>
#include <string_view>

namespace coatfft::detail {

/// `text` itself when it has at most `max_chars` characters; otherwise its first
/// max_chars - 3 characters followed by "...".
inline std::string shorten(std::string_view text, std::size_t max_chars = 80) {
  if (text.size() <= max_chars) return std::string(text);
  return std::string(text.substr(0, max_chars > 3 ? max_chars - 3 : 0)) + "...";
}

}  // namespace coatfft::detail
