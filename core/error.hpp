#pragma once
// Errors of coatfft. Library code throws; only the CLI's main turns exceptions into exit codes.
#include <charconv>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace coatfft {

/// Base of every exception coatfft throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input from the caller: a value out of range, a wrong shape, a malformed file.
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

namespace detail {
// Doubles in messages are written in their shortest round-trip form (std::to_chars), so a value
// reads as the user wrote it ("nu = 0.6", "1e-06") and still identifies the exact double.
inline void put(std::ostream& os, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  os.write(buffer, result.ptr - buffer);
}
template <typename T>
void put(std::ostream& os, const T& value) {
  os << value;
}

template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::ostringstream os;
  (put(os, parts), ...);
  return os.str();
}
}  // namespace detail

}  // namespace coatfft

/// Throws coatfft::InvalidArgument with the streamed message parts when `cond` is false.
/// Messages say what is wrong and what was expected: "Grid: nx = 0, but nx must be >= 1".
#define COATFFT_REQUIRE(cond, ...)                                                         \
  do {                                                                                     \
    if (!(cond)) throw ::coatfft::InvalidArgument(::coatfft::detail::concat(__VA_ARGS__)); \
  } while (false)
