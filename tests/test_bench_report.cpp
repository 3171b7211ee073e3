// The helpers every benchmark shares (bench/bench_report.hpp): the machine header's keys, which
// bench/results/*.csv readers (scripts/plot_pareto.py) and people rely on, and the small
// utilities' edge cases.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "core/error.hpp"

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

TEST_CASE("median is the middle value (upper middle for an even count), 0 for none") {
  CHECK(cb::median({}) == 0.0);
  CHECK(cb::median({3.0}) == 3.0);
  CHECK(cb::median({5.0, 1.0, 9.0}) == 5.0);
  CHECK(cb::median({4.0, 1.0, 3.0, 2.0}) == 3.0);
  CHECK(cb::median({1.0, 1e9, 2.0, 3.0, 1e12}) == 3.0);  // outliers do not move it
}

TEST_CASE("parse_int_list reads comma-separated integers and names a bad item") {
  CHECK(cb::parse_int_list("512,1024") == std::vector<int>{512, 1024});
  CHECK(cb::parse_int_list("7") == std::vector<int>{7});
  CHECK_THROWS_WITH(cb::parse_int_list("512,1k"), Catch::Contains("'1k'"));
  CHECK_THROWS_WITH(cb::parse_int_list("512,,2"), Catch::Contains("''"));
  CHECK_THROWS_AS(cb::parse_int_list("x"), coatfft::Error);
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
