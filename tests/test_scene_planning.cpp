// FFTW planning of a scene's operator (scene/scene.hpp, contact_measure_cells): a contact on
// 2048^2 cells or more measures its plans unless [method] planning says otherwise; a known
// pressure (one application) and smaller contacts keep "estimate".
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene.hpp"
#include "tests/scene_text.hpp"

using namespace coatfft;

namespace {

// The scene read from `text`.
scene::Scene read(const std::string& text) {
  return coatfft_test::read_scene_text(text, "coatfft_test_scene_planning");
}

std::string scene_text(int n, const std::string& load, const std::string& method) {
  return "[grid]\nnx = " + std::to_string(n) + "\nny = " + std::to_string(n) +
         "\nlx = 1e-3\nly = 1e-3\n[substrate]\nmaterial = \"steel\"\n" + load +
         "[method]\nname = \"dcfft\"\n" + method;
}

const std::string contact_section = "[contact]\nindenter = \"sphere\"\nradius = 0.01\nload = 1.0\n";
const std::string pressure_section = "[pressure]\nkind = \"hertz\"\np0 = 1e9\na = 1e-4\n";

}  // namespace

TEST_CASE("Contact scenes of 2048^2 cells or more measure their FFTW plans by default",
          "[scene][planning]") {
  CHECK(scene::contact_measure_cells == 2048 * 2048);
  CHECK(read(scene_text(2048, contact_section, "")).method.options.planning == Planning::measure);
  CHECK(read(scene_text(2046, contact_section, "")).method.options.planning == Planning::estimate);
  CHECK(read(scene_text(2048, pressure_section, "")).method.options.planning == Planning::estimate);
  // What the scene says is kept.
  const auto given = read(scene_text(2048, contact_section, "planning = \"estimate\"\n"));
  CHECK(given.method.planning_given);
  CHECK(given.method.options.planning == Planning::estimate);
  CHECK(read(scene_text(64, contact_section, "planning = \"measure\"\n")).method.options.planning ==
        Planning::measure);
}

TEST_CASE("The planning rule of reused operators (scenes' contacts, Python's make_operator)",
          "[scene][planning]") {
  const Grid large(2048, 2048, 1e-3, 1e-3), small(2047, 2048, 1e-3, 1e-3);
  scene::MethodSpec m;
  scene::plan_for_repeated_use(m, small);
  CHECK(m.options.planning == Planning::estimate);
  scene::plan_for_repeated_use(m, large);
  CHECK(m.options.planning == Planning::measure);
  scene::MethodSpec given;
  given.planning_given = true;
  scene::plan_for_repeated_use(given, large);
  CHECK(given.options.planning == Planning::estimate);
}
