#pragma once
// Errors of coatfft. Library code throws; only the CLI's main turns exceptions into exit codes.
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
template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::ostringstream os;
  os.precision(17);
  (os << ... << parts);
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
