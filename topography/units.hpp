#pragma once
// Units of length as topography files and users write them (docs/measured_surfaces.md).
#include <string_view>

namespace coatfft::topography {

/// Metres per `unit`: "m", "mm", "um", "µm" (micro sign or Greek mu), "nm", "pm", "Å" (the
/// angstrom sign or A with ring) and the spelled-out names ("metre", "meter", "micrometre",
/// "micron", "nanometre", "angstrom", ...), case-sensitive for the symbols (mm is not Mm).
/// InvalidArgument "unknown unit \"...\" in WHAT (known: ...)" otherwise.
double metres_per_unit(std::string_view unit, std::string_view what);

}  // namespace coatfft::topography
