#include "topography/units.hpp"

#include <array>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::topography {

namespace {
// The symbols and names a file or a user may write, with their size in metres. "µ" is written
// as the micro sign (U+00B5) by most instruments and as the Greek mu (U+03BC) by some; the
// angstrom as the angstrom sign (U+212B) or the letter A with ring (U+00C5).
constexpr std::array<std::pair<std::string_view, double>, 24> kUnits{{
    {"m", 1.0},           {"metre", 1.0},       {"meter", 1.0},       {"mm", 1e-3},
    {"millimetre", 1e-3}, {"millimeter", 1e-3}, {"um", 1e-6},         {"\u00b5m", 1e-6},
    {"\u03bcm", 1e-6},    {"micrometre", 1e-6}, {"micrometer", 1e-6}, {"micron", 1e-6},
    {"nm", 1e-9},         {"nanometre", 1e-9},  {"nanometer", 1e-9},  {"pm", 1e-12},
    {"picometre", 1e-12}, {"picometer", 1e-12}, {"\u00c5", 1e-10},    {"\u212b", 1e-10},
    {"A", 1e-10},         {"angstrom", 1e-10},  {"Angstrom", 1e-10},  {"\u00c5ngstr\u00f6m", 1e-10},
}};
}  // namespace

double metres_per_unit(std::string_view unit, std::string_view what) {
  for (const auto& [name, metres] : kUnits)
    if (unit == name) return metres;
  throw InvalidArgument(detail::concat("unknown unit ", io::quoted_excerpt(unit), " in ", what,
                                       " (known: m, mm, um or \u00b5m, nm, pm, \u00c5 or A)"));
}

}  // namespace coatfft::topography
