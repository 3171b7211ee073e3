#include "scene/detail/scene_method.hpp"

#include <toml++/toml.h>

#include <optional>
#include <string>

#include "core/error.hpp"
#include "scene/detail/section_reader.hpp"
#include "scene/method_request.hpp"

namespace coatfft::scene {

MethodSpec read_method(const toml::table& root, const std::filesystem::path& scene_dir,
                       Boundary boundary) {
  SectionReader reader(section(root, "method", false), "method");
  MethodRequest request;
  request.boundary = boundary;
  request.name = reader.string("name", "auto");
  const auto number = [&](const char* key) -> std::optional<double> {
    return reader.has(key) ? std::optional(reader.number(key)) : std::nullopt;
  };
  const auto text = [&](const char* key) -> std::optional<std::string> {
    return reader.has(key) ? std::optional(reader.string(key)) : std::nullopt;
  };
  request.tolerance = number("tolerance");
  request.alpha = number("alpha");
  request.g0 = text("g0");
  request.g0_tol = number("g0_tol");
  request.planning = text("planning");
  if (reader.has("threads")) request.threads = reader.integer("threads");
  request.wisdom = reader.has("wisdom");
  // omitted is not a scene's choice: the program makes it where the level of the displacement
  // does not matter (a load-controlled contact that does not report its approach).
  COATFFT_REQUIRE(request.g0 != "omitted", reader.where("g0"),
                  " = \"omitted\" is set by the program itself (a load-controlled [contact] with "
                  "report_approach = false); use \"regularized\" or \"quadrature\"");
  MethodSpec spec = method_from_request(
      request, {[&](std::string_view key) { return reader.where(key); }, "name"});
  if (request.wisdom) {
    spec.wisdom = reader.string("wisdom");
    if (spec.wisdom.is_relative()) spec.wisdom = scene_dir / spec.wisdom;
  }
  reader.finish();
  return spec;
}

void plan_for_repeated_use(MethodSpec& method, const Grid& grid) {
  if (!method.planning_given && grid.nb_cells() >= contact_measure_cells)
    method.options.planning = Planning::measure;
}

}  // namespace coatfft::scene
