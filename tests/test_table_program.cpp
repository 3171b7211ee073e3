// The table programs' shared epilogue and checks (tables/table_program.hpp): the file a table's
// write mode leaves, and the exit status of --check.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "tables/table_program.hpp"
#include "tests/test_support.hpp"

namespace {

// Standard output of `f`, captured.
template <class F>
std::string table_stdout(F&& f) {
  std::ostringstream captured;
  std::streambuf* const saved = std::cout.rdbuf(captured.rdbuf());
  f();
  std::cout.rdbuf(saved);
  return captured.str();
}

}  // namespace

TEST_CASE("write_table_file: the Markdown, then its run time, then 'wrote'", "[tables]") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "coatfft_test_table_program";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string output = (dir / "table.md").string();
  // Started 2.6 s ago: the run time is rounded to whole seconds ("%.0f").
  const auto start = std::chrono::steady_clock::now() - std::chrono::milliseconds(2600);
  int status = -1;
  const std::string out = table_stdout(
      [&] { status = coatfft::tables::write_table_file(output, "# Table\n\n| a |\n", start); });
  CHECK(status == 0);
  CHECK(out == "wrote " + output + "\n");
  CHECK(text_of(output) == "# Table\n\n| a |\n\nRun time 3 s.\n");
  std::filesystem::remove_all(dir);
}

TEST_CASE("Checks: 0 only when every comparison of at least one passed", "[tables]") {
  using coatfft::tables::Checks;
  Checks none("t");
  CHECK(table_stdout([&] { CHECK(none.finish() == 1); }) ==
        "t --check: 0 of 0 comparisons passed\n");
  Checks passing("t");
  passing.expect(true, "row", "never printed");
  CHECK(table_stdout([&] { CHECK(passing.finish() == 0); }) ==
        "t --check: 1 of 1 comparisons passed\n");
  Checks failing("t");
  const std::string line = table_stdout([&] {
    failing.expect(true, "a", "fine");
    failing.expect(false, "b | N = 8", "error 2 beyond 1");
  });
  CHECK(line == "t --check: FAILED b | N = 8: error 2 beyond 1\n");
  CHECK(table_stdout([&] { CHECK(failing.finish() == 1); }) ==
        "t --check: 1 of 2 comparisons passed\n");
}
