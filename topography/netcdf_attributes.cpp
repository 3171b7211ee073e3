#include "topography/netcdf_attributes.hpp"

#include <netcdf.h>

#include <cstddef>

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::topography {

namespace {
struct AttributeShape {
  nc_type type = NC_NAT;
  std::size_t length = 0;
};

// The attribute's type and length, or nothing where the variable has no such attribute.
std::optional<AttributeShape> shape_of(const io::NetcdfFile& nc, int var, const char* name) {
  AttributeShape shape;
  if (nc_inq_att(nc.id(), var, name, &shape.type, &shape.length) != NC_NOERR) return {};
  return shape;
}

bool is_text(nc_type type) {
  return type == NC_CHAR || type == NC_STRING;
}

// "the attribute NAME of OWNER", for messages.
std::string attribute_label(const io::NetcdfFile& nc, const char* owner, const char* name) {
  return detail::concat(nc.path().string(), ": the attribute ", name, " of ", owner);
}

// netcdf-c's name of a type ("int", "double", or a user-defined type's name).
std::string type_name(const io::NetcdfFile& nc, nc_type type) {
  char name[NC_MAX_NAME + 1] = {};
  if (nc_inq_type(nc.id(), type, name, nullptr) != NC_NOERR) return "an unknown type";
  return name;
}
}  // namespace

std::optional<std::string> text_attribute(const io::NetcdfFile& nc, int var, const char* owner,
                                          const char* name) {
  const auto shape = shape_of(nc, var, name);
  if (!shape) return {};
  COATFFT_REQUIRE(is_text(shape->type), attribute_label(nc, owner, name), " is of type ",
                  type_name(nc, shape->type), ", not text");
  if (shape->type == NC_STRING) {
    COATFFT_REQUIRE(shape->length == 1, attribute_label(nc, owner, name), " holds ", shape->length,
                    " strings, not one text");
    char* text = nullptr;
    io::check_netcdf(nc_get_att_string(nc.id(), var, name, &text), nc.path(), name);
    std::string out = text ? text : "";
    nc_free_string(1, &text);
    return out;
  }
  std::string text(shape->length, '\0');
  io::check_netcdf(nc_get_att_text(nc.id(), var, name, text.data()), nc.path(), name);
  while (!text.empty() && text.back() == '\0') text.pop_back();
  return text;
}

std::vector<double> number_attributes(const io::NetcdfFile& nc, int var, const char* owner,
                                      const char* name) {
  const auto shape = shape_of(nc, var, name);
  if (!shape) return {};
  if (is_text(shape->type)) {
    const std::string text = text_attribute(nc, var, owner, name).value_or("");
    throw InvalidArgument(detail::concat(attribute_label(nc, owner, name), " is the text ",
                                         io::quoted_excerpt(text), ", not a number"));
  }
  COATFFT_REQUIRE(shape->type <= NC_MAX_ATOMIC_TYPE && shape->length > 0,
                  attribute_label(nc, owner, name), " is of type ", type_name(nc, shape->type),
                  " with ", shape->length, " values, not a number");
  std::vector<double> values(shape->length);
  io::check_netcdf(nc_get_att_double(nc.id(), var, name, values.data()), nc.path(), name);
  return values;
}

std::optional<double> number_attribute(const io::NetcdfFile& nc, int var, const char* owner,
                                       const char* name) {
  const std::vector<double> values = number_attributes(nc, var, owner, name);
  if (values.empty()) return {};
  COATFFT_REQUIRE(values.size() == 1, attribute_label(nc, owner, name), " holds ", values.size(),
                  " numbers, not one");
  return values.front();
}

}  // namespace coatfft::topography
