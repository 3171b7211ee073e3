#pragma once
// How hard FFTW plans an operator's transforms.
#include <string_view>

namespace coatfft {

/// FFTW planner effort: `estimate` plans in microseconds (tests, one-off transforms); `measure`
/// times candidate algorithms (seconds for large sizes) and pays off for operators applied often.
enum class Planning { estimate, measure };

/// "estimate" or "measure".
std::string_view to_string(Planning planning);
/// The Planning named `name`; throws InvalidArgument naming the valid names otherwise.
Planning parse_planning(std::string_view name);

}  // namespace coatfft
