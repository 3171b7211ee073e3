// libFuzzer target: coatfft::scene::read_scene on arbitrary bytes written as scene.toml.
// InvalidArgument is the expected refusal; any other exception escapes and, like a crash or a
// sanitizer report, is a finding. The scene's folder holds small height maps and pressure files
// (h.npy, h.csv: shape (3, 4)), so that scenes naming them by relative path get past the read.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "io/npy.hpp"
#include "scene/scene.hpp"

namespace {

void write_input_maps(const coatfft::fuzz::ScratchFolder& folder) {
  coatfft::Field h(4, 3);
  for (Eigen::Index k = 0; k < h.size(); ++k) h(k) = 1e-6 * static_cast<double>(k % 5);
  coatfft::io::write_npy(folder.folder() / "h.npy", h);
  folder.write("h.csv", "0, 1e-6, 2e-6, 0\n1e-6, 0, 0, 1e-6\n0, 0, 3e-6, 0\n");
}

const coatfft::fuzz::ScratchFolder& scratch() {
  static const coatfft::fuzz::ScratchFolder folder("fuzz_scene");
  static const bool ready = (write_input_maps(folder), true);
  (void)ready;
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = scratch().write("scene.toml", data, size);
  try {
    const coatfft::scene::Scene scene = coatfft::scene::read_scene(path);
    // A scene is either a known load or a contact, never both or neither.
    if (scene.pressure.has_value() == scene.contact.has_value()) __builtin_trap();
  } catch (const coatfft::InvalidArgument&) {
  }
  return 0;
}
