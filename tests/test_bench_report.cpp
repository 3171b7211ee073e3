// The helpers every benchmark shares (bench/bench_report.hpp): the machine header's keys, which
// bench/results/*.csv readers (scripts/plot_pareto.py) and people rely on, and the result file's
// writing. (Medians: core/detail/timing.hpp, tests/test_core_detail.cpp; lists of numbers on the
// command line: CLI11, tests/test_bench_sweep.cpp.)
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"

namespace cb = coatfft::bench;

TEST_CASE("write_machine_header writes the documented keys, one '# key = value' per line") {
  std::ostringstream os;
  cb::write_machine_header(os);
  std::istringstream in(os.str());
  std::vector<std::string> keys;
  std::string line;
  while (std::getline(in, line)) {
    REQUIRE(line.rfind("# ", 0) == 0);
    const auto eq = line.find(" = ");
    REQUIRE(eq != std::string::npos);
    REQUIRE(eq + 3 < line.size());  // a value, not an empty field
    keys.push_back(line.substr(2, eq - 2));
  }
  CHECK(keys ==
        std::vector<std::string>{"date", "cpu", "hardware_threads", "compiler", "flags", "fftw"});
  CHECK(os.str().find("fftw-3") != std::string::npos);  // FFTW's own version string
}

TEST_CASE("write_text_file creates the folder, writes the text, and names a path it cannot write") {
  const auto dir = std::filesystem::temp_directory_path() / "coatfft_test_bench_report";
  std::filesystem::remove_all(dir);
  const std::string path = (dir / "sub" / "out.csv").string();
  cb::write_text_file(path, "a,b\n1,2\n");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == "a,b\n1,2\n");
  std::filesystem::remove_all(dir);
  CHECK_THROWS_WITH(cb::write_text_file("/proc/coatfft_no_such_dir/x.csv", "x"),
                    Catch::Contains("/proc/coatfft_no_such_dir/x.csv"));
}
