#pragma once
// numpy arrays <-> coatfft Fields. A Field is (nx, ny) column-major (core/types.hpp): the same
// memory as a C-order numpy array of shape (ny, nx) whose row j is y_j, the layout of the .npy
// files the CLI writes. So a field crosses the boundary as one copy in and no copy out.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string_view>
#include <vector>

#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft::python {

/// A float64, C-contiguous array: numpy converts other dtypes and layouts on the way in.
using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

/// InvalidArgument (ValueError) unless `array` has the shape (ny, nx) of `grid`; `what` names it.
void check_shape(const pybind11::array& array, const Grid& grid, std::string_view what);

/// Copies the (ny, nx) array into `field` (resized to (nx, ny)): InvalidArgument for a value not
/// finite. Reads only the array's memory, so it may run without the GIL.
void copy_into_field(const DoubleArray& array, Field& field, std::string_view what);

/// The (ny, nx) array `array` as a Field of `grid`'s shape: check_shape, then copy_into_field.
Field field_from_array(const DoubleArray& array, const Grid& grid, std::string_view what);

/// Where a result of shape (ny, nx) goes: a new array when `out` is None, else `out` itself,
/// which must be a writable, C-contiguous float64 array of that shape (ValueError; TypeError for
/// an object that is no array).
pybind11::array_t<double> output_array(const pybind11::object& out, const Grid& grid,
                                       std::string_view what);

/// `field` (nx, ny) as a numpy array of shape (ny, nx) that owns it (no copy).
pybind11::array_t<double> array_from_field(Field&& field);

/// A 1-D or n-D array of doubles with the shape of `like`, values from `values` (no copy).
pybind11::array_t<double> array_like(const DoubleArray& like, std::vector<double>&& values);

/// Fields of one kind (each (nx, ny)), stacked as (n, ny, nx) when `stacked`, else the last one
/// as (ny, nx): the layout of the program's stacked .npy files.
template <typename Array>
pybind11::array stacked_array(const std::vector<Array>& fields, bool stacked) {
  using T = typename Array::Scalar;
  const auto nx = static_cast<pybind11::ssize_t>(fields.back().rows());
  const auto ny = static_cast<pybind11::ssize_t>(fields.back().cols());
  std::vector<pybind11::ssize_t> shape = {ny, nx};
  if (stacked) shape.insert(shape.begin(), static_cast<pybind11::ssize_t>(fields.size()));
  pybind11::array_t<T> out(shape);
  T* data = out.mutable_data();
  for (std::size_t k = stacked ? 0 : fields.size() - 1; k < fields.size(); ++k)
    data = std::copy(fields[k].data(), fields[k].data() + fields[k].size(), data);
  return out;
}

}  // namespace coatfft::python
