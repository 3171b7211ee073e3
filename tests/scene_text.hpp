#pragma once
// A scene read from its text: written to a file of its own in a fresh temporary folder (removed
// again), as read_scene takes a path.
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene.hpp"

namespace coatfft_test {

inline coatfft::scene::Scene read_scene_text(const std::string& text, const std::string& folder) {
  const auto dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  const auto path = dir / "scene.toml";
  std::ofstream(path) << text;
  struct Remove {
    std::filesystem::path dir;
    ~Remove() { std::filesystem::remove_all(dir); }
  } remove{dir};
  return coatfft::scene::read_scene(path);
}

}  // namespace coatfft_test
