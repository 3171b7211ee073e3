// What a scene's computation reports to its progress observer (scene/progress_observer.hpp): a
// step for each group of stress planes' kernels and for each plane's maxima, each value of a sweep
// and each normal solve of a friction coupling, with the contact iterations between them, so that
// a front end can say which one a long run is on.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "loads/hertz_pressure.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_stress.hpp"
#include "tests/test_materials.hpp"

namespace fs = std::filesystem;
using namespace coatfft;

namespace {

// Every report, in order: "stage: ...", "step: ...", or "iteration" (one per iteration).
struct Recorder : scene::ProgressObserver {
  std::vector<std::string> events;
  void stage(std::string_view what) override { events.push_back("stage: " + std::string(what)); }
  void step(std::string_view what) override { events.push_back("step: " + std::string(what)); }
  void iteration(int, double) override { events.push_back("iteration"); }
  std::vector<std::string> steps() const {
    std::vector<std::string> s;
    for (const std::string& e : events)
      if (e.starts_with("step: ")) s.push_back(e.substr(6));
    return s;
  }
  // Whether a contact iteration follows each step (before the next step or stage).
  bool iterations_after_each_step() const {
    for (std::size_t i = 0; i < events.size(); ++i)
      if (events[i].starts_with("step: ") &&
          (i + 1 == events.size() || events[i + 1] != "iteration"))
        return false;
    return true;
  }
};

fs::path write_scene(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_scene_progress_tests";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// A sphere on a periodic steel surface, 32^2 cells; `contact_keys` ends the [contact] section.
std::string sphere_scene(const std::string& contact_keys) {
  return "[substrate]\nmaterial = \"steel\"\n[grid]\nboundary = \"periodic\"\nnx = 32\nny = 32\n"
         "lx = 3.0e-3\nly = 3.0e-3\n[contact]\nindenter = \"paraboloid\"\nradius = 0.01\n" +
         contact_keys;
}

}  // namespace

TEST_CASE("the stresses report each group of planes' kernels and each plane's maxima",
          "[scene_progress]") {
  // 20 planes on 8^2 cells: three groups of kernels (8 + 8 + 4 planes on one side).
  const Grid grid(8, 8, 4e-3, 4e-3);
  const LayerStack body(steel);
  scene::StressSpec spec;
  for (int k = 1; k <= 20; ++k) spec.depths.push_back(2e-4 * k);
  spec.alpha = 2;
  const Field p = hertz_pressure(grid, 1.0, 1e-3, Sampling::cell_average);
  Recorder progress;
  scene::compute_stress(spec, body, grid, p, {}, 1, progress);
  std::vector<std::string> expected = {"kernels of planes 1 to 8 of 20",
                                       "kernels of planes 9 to 16 of 20",
                                       "kernels of planes 17 to 20 of 20", "convolutions"};
  for (int k = 1; k <= 20; ++k)
    expected.push_back("maxima of plane " + std::to_string(k) + " of 20");
  CHECK(progress.steps() == expected);
}

TEST_CASE("a sweep reports each value, its iterations after it", "[scene_progress]") {
  Recorder progress;
  scene::SceneRunOptions options;
  options.progress = &progress;
  scene::run_scene(write_scene("sweep.toml", sphere_scene("load = [40.0, 10.0, 20.0]\n")), options);
  // Ascending, as the sweep solves them.
  CHECK(progress.steps() ==
        std::vector<std::string>{"load 1 of 3: 10 N", "load 2 of 3: 20 N", "load 3 of 3: 40 N"});
  CHECK(progress.iterations_after_each_step());
}

TEST_CASE("a friction coupling reports each normal solve", "[scene_progress]") {
  Recorder progress;
  scene::SceneRunOptions options;
  options.progress = &progress;
  const scene::SceneRun run = scene::run_scene(
      write_scene("friction.toml", sphere_scene("load = 10.0\nfriction = 0.3\n")), options);
  const int solves = run.summary["friction_coupling"]["solves"].get<int>();
  REQUIRE(solves >= 2);
  std::vector<std::string> expected;
  for (int k = 1; k <= solves; ++k)
    expected.push_back("friction coupling: normal solve " + std::to_string(k) + " of at most 30");
  CHECK(progress.steps() == expected);
  CHECK(progress.iterations_after_each_step());
}
