#pragma once
// The attributes the NetCDF topography reader takes (units, length, periodic, CF's packing and
// missing values), read with their type checked: an attribute that is there but of the wrong
// type (`scale_factor = "abc"`, a numeric `units`) is refused on one line naming it and the
// variable, rather than ignored, since ignoring it would read the heights in another scale or
// unit than the file's author meant.
#include <optional>
#include <string>
#include <vector>

#include "io/netcdf_file.hpp"

namespace coatfft::topography {

/// The text of attribute `name` of variable `var` (named `owner` in messages): NC_CHAR, or one
/// NC_STRING (what netCDF4-python writes in NETCDF4 files for text beyond ASCII, such as "µm");
/// nothing where the attribute is absent. Any other type is refused.
std::optional<std::string> text_attribute(const io::NetcdfFile& nc, int var, const char* owner,
                                          const char* name);

/// The values of numeric attribute `name` of `var`, as doubles (CF allows several for
/// missing_value); empty where absent. Text is refused.
std::vector<double> number_attributes(const io::NetcdfFile& nc, int var, const char* owner,
                                      const char* name);

/// The one value of numeric attribute `name` of `var`; nothing where absent. Text and lists are
/// refused.
std::optional<double> number_attribute(const io::NetcdfFile& nc, int var, const char* owner,
                                       const char* name);

}  // namespace coatfft::topography
