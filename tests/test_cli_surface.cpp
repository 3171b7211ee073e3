// `coatfft surface`: the file it writes (shape, rms as asked, the same bytes for the same seed)
// and its refusals (one line, exit 2, no file).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "io/npy.hpp"
#include "tests/address_sanitized.hpp"
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
  const coatfft::Field h = coatfft::io::read_npy(a);
  CHECK(h.rows() == 64);  // (ny, nx) on disk, (nx, ny) in memory
  CHECK(h.cols() == 48);
  CHECK(std::sqrt(h.square().mean()) == Approx(0.5e-6).epsilon(1e-12));
  REQUIRE(run_coatfft("surface -o " + b.string() + kSurface + " --rms-height 0.5e-6").status == 0);
  CHECK(bytes_of(a) == bytes_of(b));
  REQUIRE(run_coatfft("surface -o " + b.string() + kSurface +
                      " --rms-height 0.5e-6 --seed 3 --overwrite")
              .status == 0);
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

TEST_CASE("a scene's measured topography is pressed by a rigid flat, its tilt removed on request",
          "[cli][topography]") {
  // The topography of `coatfft surface` (peaks up) as [contact] topography equals the height map
  // max(z) - z the user would have formed; tilted on the stage and detrended with "plane", the
  // same contact to the solver's accuracy (the plane's removal rounds the gap).
  const fs::path z_file = scratch("topography_z.npy");
  fs::remove(z_file);
  REQUIRE(run_coatfft("surface -o " + z_file.string() +
                      " --nx 32 --ny 32 --lx 0.25e-3 --ly 0.25e-3 --hurst 0.8 --rms-height 0.2e-6"
                      " --seed 4")
              .status == 0);
  const coatfft::Field z = coatfft::io::read_npy(z_file);
  coatfft::io::write_npy(scratch("topography_gap.npy"), z.maxCoeff() - z);
  coatfft::Field tilted = z;
  const double dx = 0.25e-3 / 32;
  for (Eigen::Index j = 0; j < 32; ++j)
    for (Eigen::Index i = 0; i < 32; ++i)
      tilted(i, j) += 2e-3 * (i + 0.5 - 16) * dx - 1e-3 * (j + 0.5 - 16) * dx + 1e-6;
  coatfft::io::write_npy(scratch("topography_tilted.npy"), tilted);
  const std::string base =
      "[grid]\nnx = 32\nny = 32\nlx = 0.25e-3\nly = 0.25e-3\nboundary = \"periodic\"\n"
      "[substrate]\nmaterial = \"steel\"\n[contact]\nload = 0.5\n";
  const auto run = [&](const std::string& keys, const std::string& name) {
    return run_scene_ok(base + keys, name);
  };
  const fs::path from_map =
      run("indenter = \"height_map\"\npath = \"" + scratch("topography_gap.npy").string() + "\"\n",
          "topography_map");
  const fs::path from_z = run("topography = \"" + z_file.string() + "\"\n", "topography_z");
  const fs::path from_tilt = run(
      "topography = \"" + scratch("topography_tilted.npy").string() + "\"\ndetrend = \"plane\"\n",
      "topography_tilted");
  const coatfft::Field p_map = coatfft::io::read_npy(from_map / "pressure.npy");
  CHECK((coatfft::io::read_npy(from_z / "pressure.npy") - p_map).abs().maxCoeff() == 0.0);
  // The untilted z has its own small plane (its rms slope is not zero): compare against z
  // detrended the same way.
  const fs::path from_plane =
      run("topography = \"" + z_file.string() + "\"\ndetrend = \"plane\"\n", "topography_plane");
  const coatfft::Field p_plane = coatfft::io::read_npy(from_plane / "pressure.npy");
  CHECK((coatfft::io::read_npy(from_tilt / "pressure.npy") - p_plane).abs().maxCoeff() <
        1e-6 * p_plane.maxCoeff());
  CHECK(read_summary(from_z)["indenter"] == "topography");
}

TEST_CASE("a measured topography's refusals", "[cli][topography]") {
  const std::string base =
      "[grid]\nnx = 8\nny = 8\nlx = 1e-3\nly = 1e-3\n[substrate]\nmaterial = \"steel\"\n"
      "[contact]\nindenter = \"sphere\"\nradius = 0.01\nload = 1.0\n";
  const BadCase cases[] = {
      {"topography_and_indenter", "load = 1.0", "load = 1.0\ntopography = \"z.npy\"", "not both"},
      {"detrend_without_topography", "load = 1.0", "load = 1.0\ndetrend = \"plane\"", "topography"},
      {"topography_bad_detrend", "indenter = \"sphere\"\nradius = 0.01",
       "topography = \"z.npy\"\ndetrend = \"tilt\"", "detrend"},
  };
  for (const BadCase& c : cases) check_refused(base, c);
}

TEST_CASE("coatfft topography and surface leave an existing output file as it is",
          "[cli][topography][cli_surface]") {
  // The user's own file under each name, .npy and .nc alike: refused on one line naming it and
  // --overwrite (exit 2), its bytes unchanged; replaced only with --overwrite.
  const fs::path z = scratch("exists_z.npy");
  fs::remove(z);
  REQUIRE(run_coatfft("surface -o " + z.string() + kSurface + " --rms-height 1e-6").status == 0);
  for (const char* name : {"exists_mine.npy", "exists_mine.nc"}) {
    const fs::path mine = scratch(name);
    std::ofstream(mine, std::ios::binary) << "the user's own bytes";
    for (const std::string& command :
         {"surface -o " + mine.string() + kSurface + " --rms-height 1e-6",
          "topography " + z.string() + " --lx 1e-3 --ly 0.75e-3 -o " + mine.string()}) {
      INFO(command);
      const auto r = run_coatfft(command);
      CHECK(r.status == 2);
      CHECK(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n') == 1);
      CHECK(r.stderr_text.find(mine.string() + "\" exists") != std::string::npos);
      CHECK(r.stderr_text.find("--overwrite") != std::string::npos);
      CHECK(bytes_of(mine) == "the user's own bytes");
      CHECK(run_coatfft(command + " --overwrite").status == 0);
      CHECK(bytes_of(mine) != "the user's own bytes");
      std::ofstream(mine, std::ios::binary) << "the user's own bytes";
    }
  }
}

namespace {
// `coatfft ARGS` with its standard output (the topography's summary) read as JSON; its status.
int summary_of(const std::string& args, nlohmann::json& summary) {
  const fs::path out = scratch("topography_summary.json");
  const int raw = std::system(
      (std::string(COATFFT_EXE) + " " + args + " >" + out.string() + " 2>/dev/null").c_str());
  std::ifstream in(out);
  if (WIFEXITED(raw) && WEXITSTATUS(raw) == 0) in >> summary;
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}
}  // namespace

TEST_CASE(
    "coatfft topography: heights near the largest double give a finite summary or a "
    "refusal naming the file",
    "[cli][topography]") {
  // 2 x 2 heights of +-1.7e308 (rows 1.7e308 -1.7e308 and -1.7e308 1.7e308): the mean is 0 and
  // Sq = 1.7e308, which squares of the heights cannot reach; the gap max(z) - z = 3.4e308 and
  // the rms slope (steps of 3.4e308 m over 1 m) are beyond the largest double.
  const fs::path h = scratch("overflow_h.csv");
  std::ofstream(h) << "1.7e308,-1.7e308\n-1.7e308,1.7e308\n";
  nlohmann::json s;
  REQUIRE(summary_of("topography " + h.string(), s) == 0);
  CHECK(s["rms_height"].get<double>() == Approx(1.7e308).epsilon(1e-15));
  const fs::path g = scratch("overflow_g.npy");
  fs::remove(g);
  for (const std::string& args : {" --gap -o " + g.string(), std::string(" --lx 2 --ly 2")}) {
    const auto r = run_coatfft("topography " + h.string() + args);
    INFO(r.stderr_text);
    CHECK(r.status == 2);
    CHECK(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n') == 1);
    CHECK(r.stderr_text.find(h.string() + ": ") != std::string::npos);
    CHECK(r.stderr_text.find("beyond the largest double") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(g));
  // A map of 1e200 times z = i + 2 j on 3 x 2 points (x along columns): heights 0, 1, 2 and
  // 2, 3, 4, mean 2, Sq = sqrt(10/6); steps 1 along x (spacing 1 m) and 2 along y: Sdq = sqrt(5).
  const fs::path big = scratch("overflow_big.csv");
  std::ofstream(big) << "0,1e200,2e200\n2e200,3e200,4e200\n";
  REQUIRE(summary_of("topography " + big.string() + " --lx 3 --ly 2", s) == 0);
  CHECK(s["rms_height"].get<double>() == Approx(1e200 * std::sqrt(10.0 / 6.0)).epsilon(1e-14));
  CHECK(s["rms_slope"].get<double>() == Approx(1e200 * std::sqrt(5.0)).epsilon(1e-14));
}

TEST_CASE("coatfft topography: missing points named with its own flag, their fill bounded",
          "[cli][topography]") {
  const fs::path nan = scratch("missing_nan.csv");
  std::ofstream(nan) << "1,nan\n2,3\n";
  const auto r = run_coatfft("topography " + nan.string());
  CHECK(r.status == 2);
  CHECK(r.stderr_text.find("(--missing fill") != std::string::npos);
  CHECK(r.stderr_text.find("missing = ") == std::string::npos);
  // One known point on 512^2: 262143 points to fill, about 0.13 GB before the factor, refused
  // under --max-memory 20M before it is allocated (the address space is limited to 150 MB, less
  // than the fill's 178 MB peak; the time to 20 s).
  coatfft::Field one = coatfft::Field::Constant(512, 512, std::nan(""));
  one(7, 9) = 1e-6;
  const fs::path map = scratch("missing_one.npy");
  coatfft::io::write_npy(map, one);
  const auto bounded =
      run_coatfft("topography " + map.string() + " --missing fill --max-memory 20M",
                  // A sanitized program reserves terabytes of address space for its shadow.
                  address_sanitized() ? "timeout 20" : "timeout 20 prlimit --as=150000000");
  INFO(bounded.stderr_text);
  CHECK(bounded.status == 2);
  CHECK(std::count(bounded.stderr_text.begin(), bounded.stderr_text.end(), '\n') == 1);
  CHECK(bounded.stderr_text.find(map.string() + ": filling the missing points needs about") !=
        std::string::npos);
  CHECK(bounded.stderr_text.find("262143 missing points") != std::string::npos);
}
