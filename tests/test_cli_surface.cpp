// `coatfft surface`: the file it writes (shape, rms as asked, the same bytes for the same seed)
// and its refusals (one line, exit 2, no file).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "scene/npy.hpp"
#include "tests/cli_process.hpp"

using namespace coatfft_test;

namespace {

const std::string kSurface = " --nx 64 --ny 48 --lx 1e-3 --ly 0.75e-3 --hurst 0.8";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One refused `coatfft surface` command line: exit 2, one line naming `must_mention`, no file.
struct SurfaceCase {
  const char* name;
  std::string args;
  const char* must_mention;
};

void check_surface_refused(const SurfaceCase& c, const std::string& prefix) {
  INFO(c.name);
  const fs::path out = scratch(prefix + c.name + ".npy");
  fs::remove(out);
  const auto r = run_coatfft("surface -o " + out.string() + c.args);
  INFO(r.stderr_text);
  CHECK(r.status == 2);
  CHECK(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n') == 1);
  CHECK(r.stderr_text.find(c.must_mention) != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

}  // namespace

TEST_CASE("coatfft surface writes a reproducible self-affine surface", "[cli_surface]") {
  const fs::path a = scratch("surface_a.npy"), b = scratch("surface_b.npy");
  fs::remove(a);
  fs::remove(b);
  const auto r = run_coatfft("surface -o " + a.string() + kSurface + " --rms-height 0.5e-6");
  INFO(r.stderr_text);
  REQUIRE(r.status == 0);
  const coatfft::Field h = coatfft::scene::read_npy(a);
  CHECK(h.rows() == 64);  // (ny, nx) on disk, (nx, ny) in memory
  CHECK(h.cols() == 48);
  CHECK(std::sqrt(h.square().mean()) == Approx(0.5e-6).epsilon(1e-12));
  REQUIRE(run_coatfft("surface -o " + b.string() + kSurface + " --rms-height 0.5e-6").status == 0);
  CHECK(bytes_of(a) == bytes_of(b));
  REQUIRE(
      run_coatfft("surface -o " + b.string() + kSurface + " --rms-height 0.5e-6 --seed 3").status ==
      0);
  CHECK(bytes_of(a) != bytes_of(b));
}

TEST_CASE("coatfft surface refuses bad options with one line and writes nothing", "[cli_surface]") {
  const SurfaceCase cases[] = {
      {"odd", " --nx 63 --ny 48 --lx 1e-3 --ly 1e-3 --hurst 0.8 --rms-height 1e-6", "--nx"},
      {"both_rms", kSurface + " --rms-height 1e-6 --rms-slope 0.1", "exactly one"},
      {"no_rms", kSurface, "exactly one"},
      {"hurst", " --nx 64 --ny 48 --lx 1e-3 --ly 1e-3 --hurst 0 --rms-height 1e-6", "Hurst"},
      {"cutoff", kSurface + " --rms-height 1e-6 --short-cutoff 1e-6", "short cut-off"},
      {"length", " --nx 64 --ny 48 --lx -1 --ly 1e-3 --hurst 0.8 --rms-height 1e-6", "--lx"},
  };
  for (const auto& c : cases) check_surface_refused(c, "surface_bad_");
  const fs::path txt = scratch("surface_bad.txt");
  const auto r = run_coatfft("surface -o " + txt.string() + kSurface + " --rms-height 1e-6");
  CHECK(r.status == 2);
  CHECK(r.stderr_text.find(".npy") != std::string::npos);
  CHECK_FALSE(fs::exists(txt));
}

TEST_CASE("coatfft surface refuses rms values, seeds and outputs it cannot honour, by flag",
          "[cli_surface]") {
  const SurfaceCase cases[] = {
      // Heights of 1e296 m would overflow the printed rms (it read "inf" and "-nan").
      {"slope_huge", kSurface + " --rms-slope 1e300", "--rms-slope"},
      // A denormal rms height rounded the surface to zeros ("0 m").
      {"height_denormal", kSurface + " --rms-height 1e-320", "--rms-height"},
      {"height_huge", kSurface + " --rms-height 2", "--rms-height"},
      // A slope within its own range whose surface would be sub-femtometre.
      {"slope_tiny", kSurface + " --rms-slope 1e-14", "--rms-slope"},
      // CLI11 saturated these two to 2^64 - 1: the same surface as the largest seed.
      {"seed_negative", kSurface + " --rms-height 1e-6 --seed -1", "--seed"},
      {"seed_2p64", kSurface + " --rms-height 1e-6 --seed 18446744073709551616", "--seed"},
      {"seed_exponent", kSurface + " --rms-height 1e-6 --seed 1e23", "--seed"},
      {"seed_fraction", kSurface + " --rms-height 1e-6 --seed 1.5", "--seed"},
  };
  for (const auto& c : cases) check_surface_refused(c, "surface_limit_");
  // The largest seed is a seed like any other.
  const fs::path top = scratch("surface_seed_top.npy");
  fs::remove(top);
  CHECK(run_coatfft("surface -o " + top.string() + kSurface +
                    " --rms-height 1e-6 --seed 18446744073709551615")
            .status == 0);
  CHECK(fs::exists(top));
}

TEST_CASE("coatfft surface names a missing output directory as given, not its staging file",
          "[cli_surface]") {
  const fs::path dir = scratch("surface_missing_dir");
  fs::remove_all(dir);
  const std::string target = (dir / "x.npy").string();
  const auto r = run_coatfft("surface -o " + target + kSurface + " --rms-height 1e-6");
  INFO(r.stderr_text);
  CHECK(r.status == 2);
  CHECK(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n') == 1);
  CHECK(r.stderr_text.find("does not exist") != std::string::npos);
  CHECK(r.stderr_text.find(dir.string()) != std::string::npos);
  CHECK(r.stderr_text.find(".partial") == std::string::npos);
  CHECK_FALSE(fs::exists(dir));
}
