#pragma once
// Small pieces the topography readers share (x3p_topography.cpp, sdf_topography.cpp).
#include <filesystem>
#include <string_view>

#include "core/error.hpp"

namespace coatfft::topography {

/// Refuses the file: InvalidArgument "PATH: parts...".
template <typename... Parts>
[[noreturn]] void refuse(const std::filesystem::path& path, const Parts&... parts) {
  throw InvalidArgument(detail::concat(path.string(), ": ", parts...));
}

/// `text` less its leading and trailing white space (blanks, tabs, line ends, form feeds).
inline std::string_view trimmed(std::string_view text) {
  constexpr std::string_view space = " \t\r\n\f\v";
  const auto first = text.find_first_not_of(space);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(space) - first + 1);
}

}  // namespace coatfft::topography
