#pragma once
// How hard FFTW plans an operator's transforms, and in which precision they run.
#include <string_view>

namespace coatfft {

/// FFTW planner effort: `estimate` plans in microseconds (tests, one-off transforms); `measure`
/// times candidate algorithms (seconds for large sizes) and pays off for operators applied often.
enum class Planning { estimate, measure };

/// "estimate" or "measure".
std::string_view to_string(Planning planning);
/// The Planning named `name`; throws InvalidArgument naming the valid names otherwise.
Planning parse_planning(std::string_view name);

/// The floating-point precision of an operator's FFTs. `single` runs them in FFTW's
/// single-precision library (fields stay double outside the transforms): a relative error of
/// about 1e-7 per application, for applications up to twice as fast on large grids
/// (docs/benchmarks.md, "Single precision"). Periodic operators only.
enum class Precision { double_precision, single };

/// "double" or "single".
std::string_view to_string(Precision precision);

}  // namespace coatfft
