// A misspelt scene key is named as the likely slip (scene/key_spelling.hpp): the optimal string
// alignment distance against hand-counted edits, and the refusals of scenes with one slip.
#include <catch2/catch.hpp>
#include <string>

#include "core/error.hpp"
#include "scene/key_spelling.hpp"
#include "scene/scene.hpp"
#include "tests/scene_text.hpp"

using namespace coatfft;

namespace {

// The message read_scene refuses `text` with ("" when it reads).
std::string refusal(const std::string& text) {
  try {
    coatfft_test::read_scene_text(text, "coatfft_test_key_spelling");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

const std::string grid = "[grid]\nnx = 32\nny = 32\nlx = 1e-3\nly = 1e-3\n";
const std::string body = "[substrate]\nmaterial = \"steel\"\n";

}  // namespace

TEST_CASE("edit distance: insertions, deletions, substitutions, transpositions",
          "[scene][bad_input]") {
  // Each pair's edits counted by hand.
  CHECK(scene::edit_distance("load", "load") == 0);
  CHECK(scene::edit_distance("lod", "load") == 1);   // a deleted 'a'
  CHECK(scene::edit_distance("laod", "load") == 1);  // 'a' and 'o' swapped
  CHECK(scene::edit_distance("loda", "load") == 1);  // 'd' and 'a' swapped
  CHECK(scene::edit_distance("lpad", "load") == 1);  // 'o' for 'p'
  CHECK(scene::edit_distance("aproach", "approach") == 1);
  CHECK(scene::edit_distance("apporach", "approach") == 1);
  CHECK(scene::edit_distance("tolerence", "tolerance") == 1);
  CHECK(scene::edit_distance("", "abc") == 3);
  CHECK(scene::edit_distance("kitten", "sitting") == 3);
  CHECK(scene::edit_distance("ca", "abc") == 3);  // no substring edited twice (OSA, not Damerau)
}

TEST_CASE("a missing key names the section's likely misspelling of it", "[scene][bad_input]") {
  const std::string contact = "[contact]\nindenter = \"sphere\"\nradius = 0.01\n";
  for (const auto& [typo, key] :
       {std::pair{"lod", "load"}, std::pair{"laod", "load"}, std::pair{"aproach", "approach"}}) {
    INFO(typo);
    const std::string message = refusal(grid + body + contact + typo + " = 1.0\n");
    CHECK(message.find(std::string("(is \"") + typo + "\" a misspelling of \"" + key + "\"?)") !=
          std::string::npos);
  }
  // A required key: [coating] thickness.
  const std::string coating = "[[coating]]\nmaterial = \"alumina\"\nthicknes = 1e-5\n";
  const std::string pressure = "[pressure]\nkind = \"hertz\"\np0 = 1e9\na = 1e-4\n";
  CHECK(refusal(grid + body + coating + pressure)
            .find("missing required key \"thickness\" (is \"thicknes\" a misspelling of "
                  "\"thickness\"?)") != std::string::npos);
  // Nothing close: no guess. Two-letter keys have valid neighbours (nx, ny): no guess either.
  const std::string far = refusal(grid + body + contact + "force = 1.0\n");
  CHECK(far.find("give exactly one of load") != std::string::npos);
  CHECK(far.find("misspelling") == std::string::npos);
  const std::string short_keys =
      refusal("[grid]\nnx = 32\nnz = 32\nlx = 1e-3\nly = 1e-3\n" + body + pressure);
  CHECK(short_keys.find("missing required key \"ny\"") != std::string::npos);
  CHECK(short_keys.find("misspelling") == std::string::npos);
}
