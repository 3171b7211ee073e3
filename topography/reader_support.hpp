#pragma once
// Small pieces the topography readers share (x3p_topography.cpp, sdf_topography.cpp,
// netcdf_topography.cpp, topography.cpp).
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "topography/topography.hpp"

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

/// `text` with its ASCII capitals made small (file extensions, hex digits, keywords).
inline std::string lower_ascii(std::string_view text) {
  std::string lower(text);
  for (char& c : lower)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return lower;
}

/// A number of type T as the whole of `text` (blanks around it and a leading '+' allowed, as
/// std::from_chars reads it otherwise); nothing for anything else.
template <typename T>
std::optional<T> parse_number(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

/// The unsigned integer of `width` (<= 8) little-endian bytes at `bytes`.
inline std::uint64_t little_endian(const char* bytes, std::size_t width) {
  std::uint64_t word = 0;
  for (std::size_t k = width; k-- > 0;)  // the last byte is the highest
    word = (word << 8) | static_cast<unsigned char>(bytes[k]);
  return word;
}

/// Refuses a map of nx x ny points whose heights (a double each) exceed the file size limit
/// `options.max_bytes`; nx ny times 8 then fits in 64 bits. `sizes` names the counts ("SizeX *
/// SizeY") as the file declares them.
void require_file_point_limit(const std::filesystem::path& path, std::string_view sizes,
                              std::size_t nx, std::size_t ny, const ReadOptions& options);

/// Refuses a map of nx x ny points (a double each) that would not fit `options.max_memory`, or
/// what the machine has available, before it is allocated.
void require_map_memory(const std::filesystem::path& path, std::string_view sizes, std::size_t nx,
                        std::size_t ny, const ReadOptions& options);

/// Both, before anything is allocated.
void require_point_limit(const std::filesystem::path& path, std::string_view sizes, std::size_t nx,
                         std::size_t ny, const ReadOptions& options);

}  // namespace coatfft::topography
