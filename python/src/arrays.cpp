#include "arrays.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace py = pybind11;

namespace coatfft::python {

namespace {
// "(3, 4)": a numpy shape as Python prints it.
std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d)
    text += (d ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}
}  // namespace

void check_shape(const py::array& array, const Grid& grid, std::string_view what) {
  // numpy turns None or a number into a 0-d array: name that, not its shape "()".
  COATFFT_REQUIRE(array.ndim() > 0, what,
                  ": got a single value (None or a number), but the grid "
                  "needs an array of shape (ny, nx) = (",
                  grid.ny(), ", ", grid.nx(), ")");
  COATFFT_REQUIRE(array.ndim() == 2 && array.shape(0) == grid.ny() && array.shape(1) == grid.nx(),
                  what, ": shape ", shape_text(array), ", but the grid needs (ny, nx) = (",
                  grid.ny(), ", ", grid.nx(), ")");
}

void copy_into_field(const DoubleArray& array, Field& field, std::string_view what) {
  // Same memory layout: row j of the C-order array is column j of the Field.
  field = Eigen::Map<const Field>(array.data(), array.shape(1), array.shape(0));
  if (field.allFinite()) return;
  for (Eigen::Index j = 0; j < field.cols(); ++j)
    for (Eigen::Index i = 0; i < field.rows(); ++i)
      COATFFT_REQUIRE(std::isfinite(field(i, j)), what, "[", j, ", ", i, "] = ", field(i, j),
                      " is not finite");
}

Field field_from_array(const DoubleArray& array, const Grid& grid, std::string_view what) {
  check_shape(array, grid, what);
  Field field;
  copy_into_field(array, field, what);
  return field;
}

py::array_t<double> output_array(const py::object& out, const Grid& grid, std::string_view what) {
  if (out.is_none()) return py::array_t<double>({grid.ny(), grid.nx()});
  if (!py::isinstance<py::array>(out))
    throw py::type_error(std::string(what) + ": expected a numpy array, not " +
                         py::str(py::type::of(out).attr("__name__")).cast<std::string>());
  const auto array = out.cast<py::array>();
  check_shape(array, grid, what);
  // The result is written into it: no conversion can stand in for the caller's own array.
  COATFFT_REQUIRE(array.dtype().is(py::dtype::of<double>()) &&
                      (array.flags() & py::array::c_style) && array.writeable(),
                  what, ": must be a writable, C-contiguous float64 array");
  return out.cast<py::array_t<double>>();
}

py::array_t<double> array_from_field(Field&& field) {
  auto* owned = new Field(std::move(field));
  py::capsule owner(owned, [](void* p) { delete static_cast<Field*>(p); });
  const auto nx = static_cast<py::ssize_t>(owned->rows());
  const auto ny = static_cast<py::ssize_t>(owned->cols());
  const auto item = static_cast<py::ssize_t>(sizeof(double));
  return py::array_t<double>({ny, nx}, {nx * item, item}, owned->data(), owner);
}

py::array_t<double> array_like(const DoubleArray& like, std::vector<double>&& values) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  std::vector<py::ssize_t> shape(like.shape(), like.shape() + like.ndim());
  return py::array_t<double>(shape, owned->data(), owner);
}

}  // namespace coatfft::python
