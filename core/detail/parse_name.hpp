#pragma once
// Names to enumerators: the one way user-facing names ("frf-split", "quadrature", "measure") are
// parsed, with the one message listing the valid names.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/detail/shorten.hpp"
#include "core/error.hpp"

namespace coatfft::detail {

/// The value of `values` whose to_string() is `name`; throws InvalidArgument
/// ("\"x\" is not one of \"a\", \"b\"") otherwise.
template <typename Enum, std::size_t N>
Enum parse_name(std::string_view name, const std::array<Enum, N>& values) {
  std::string valid;
  for (const Enum value : values) {
    if (to_string(value) == name) return value;
    valid += (valid.empty() ? "\"" : ", \"") + std::string(to_string(value)) + "\"";
  }
  throw InvalidArgument(concat("\"", shorten(name), "\" is not one of ", valid));
}

}  // namespace coatfft::detail
