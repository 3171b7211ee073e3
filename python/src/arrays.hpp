#pragma once
// numpy arrays <-> coatfft Fields. A Field is (nx, ny) column-major (core/types.hpp): the same
// memory as a C-order numpy array of shape (ny, nx) whose row j is y_j, the layout of the .npy
// files the CLI writes. So a field crosses the boundary as one copy in and no copy out.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string_view>

#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft::python {

/// A float64, C-contiguous array: numpy converts other dtypes and layouts on the way in.
using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

/// The (ny, nx) array `array` as a Field of `grid`'s shape; `what` names it in the errors
/// (InvalidArgument, i.e. ValueError): a wrong shape, or a value not finite.
Field field_from_array(const DoubleArray& array, const Grid& grid, std::string_view what);

/// `field` (nx, ny) as a numpy array of shape (ny, nx) that owns it (no copy).
pybind11::array_t<double> array_from_field(Field&& field);

/// A 1-D or n-D array of doubles with the shape of `like`, values from `values` (no copy).
pybind11::array_t<double> array_like(const DoubleArray& like, std::vector<double>&& values);

}  // namespace coatfft::python
