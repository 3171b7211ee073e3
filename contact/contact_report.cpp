#include <array>
#include <string>
#include <string_view>

#include "contact/contact_solver.hpp"
#include "core/error.hpp"

namespace coatfft {

namespace {

void append(std::string& text, const std::string& more) {
  if (!text.empty()) text += "; ";
  text += more;
}

// The sentence users see for a breakdown.
std::string breakdown_message(ContactStatus status) {
  return status == ContactStatus::pressure_vanished
             ? "all pressure vanished (breakdown)"
             : "non-positive curvature along the search direction (breakdown)";
}

}  // namespace

std::string_view to_string(ContactStatus status) {
  // In the order of the enumerators (tests/test_contact.cpp checks each name).
  static constexpr std::array<std::string_view, 5> names = {
      "converged", "iteration_limit", "pressure_vanished", "non_positive_curvature",
      "coupling_limit"};
  return names.at(static_cast<std::size_t>(status));
}

std::string describe(const ContactResult& result, double tolerance) {
  std::string text;
  const bool breakdown = result.status == ContactStatus::pressure_vanished ||
                         result.status == ContactStatus::non_positive_curvature;
  if (breakdown) append(text, breakdown_message(result.status));
  if (result.touches_boundary) {
    append(text,
           "contact reaches the domain edge (pressure > 0 on a border cell): the domain is too "
           "small for this load");
  }
  if (result.status == ContactStatus::coupling_limit) {
    append(text, "the friction coupling did not converge within its normal solves");
  }
  if (result.status == ContactStatus::iteration_limit) {
    append(text, detail::concat("not converged after ", result.iterations, " iterations (residual ",
                                result.residual, ", tolerance ", tolerance, ")"));
  }
  return text;
}

}  // namespace coatfft
