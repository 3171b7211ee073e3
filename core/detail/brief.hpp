#pragma once
// Numbers in the sentences of reports ("why" of the automatic choice): three significant digits.
#include <iomanip>
#include <sstream>
#include <string>

namespace coatfft::detail {

inline std::string brief(double value) {
  std::ostringstream os;
  os << std::setprecision(3) << value;
  return os.str();
}

}  // namespace coatfft::detail
