#include "cli/wisdom_file.hpp"

#include <iostream>
#include <string>

#include "convolution/fft/fftw_wisdom.hpp"
#include "core/error.hpp"
#include "io/input_file.hpp"
#include "scene/operator_from_scene.hpp"

namespace coatfft::cli {

namespace fs = std::filesystem;

namespace {

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  return fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec);
}

}  // namespace

void load_wisdom(const scene::Scene& scene, const StagedOutput& out) {
  const fs::path& wisdom = scene.method.wisdom;
  if (wisdom.empty()) return;
  const std::string where = "[method] wisdom = " + io::quoted_excerpt(wisdom.string());
  for (const fs::path& input : scene.input_files)
    COATFFT_REQUIRE(!same_file(wisdom, input), where, " is an input of this run (",
                    io::quoted_excerpt(input.string()), "): name a file of its own");
  for (const fs::path& target : out.targets())
    COATFFT_REQUIRE(!same_file(wisdom, target), where,
                    " is an output of this run: name a file outside the output folder's outputs");
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(wisdom, ec))) return;  // written by save_wisdom
  check_output_target(wisdom, "[method] wisdom", scene.input_files);
  const std::string text = scene::read_wisdom_file(wisdom);
  COATFFT_REQUIRE(scene::holds_fftw_wisdom(text), where,
                  " exists and does not hold FFTW wisdom (it does not start with \"(fftw-3\"): "
                  "coatfft will not overwrite it");
  if (!import_fftw_wisdom(text))
    std::cerr << "coatfft: warning: " << where
              << " could not be imported (another FFTW version?); it will be replaced\n";
}

void save_wisdom(const fs::path& wisdom, const std::vector<fs::path>& inputs) {
  if (!wisdom.empty())
    write_file_atomically(wisdom, "[method] wisdom", export_fftw_wisdom(), inputs);
}

}  // namespace coatfft::cli
