#pragma once
// The names of load shapes and samplings as Python passes them: "hertz", "uniform_disk";
// "centre", "cell_average". InvalidArgument (ValueError) for another name.
#include <string_view>

#include "loads/axisymmetric_load.hpp"
#include "loads/sampling.hpp"

namespace coatfft::python {

Sampling parse_sampling(std::string_view name);
AxisymmetricLoad parse_load(std::string_view name);

}  // namespace coatfft::python
