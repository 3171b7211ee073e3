// The .npy and CSV readers and writers of the CLI.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "cli/npy.hpp"

namespace fs = std::filesystem;
using coatfft::Field;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_npy_tests";
  fs::create_directories(dir);
  return dir / name;
}

// A version 1.0 .npy file with the given header dict and `nb_values` doubles 0, 1, 2, ...
fs::path npy_with_header(const std::string& name, std::string dict, int nb_values) {
  dict.append((64 - (10 + dict.size() + 1) % 64) % 64, ' ');
  dict.push_back('\n');
  const fs::path path = scratch(name);
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  out.put(static_cast<char>(dict.size() & 0xff));
  out.put(static_cast<char>(dict.size() >> 8));
  out << dict;
  for (int n = 0; n < nb_values; ++n) {
    const double v = n;
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  return path;
}

}  // namespace

TEST_CASE("npy: write then read round-trips shape and values", "[cli][npy]") {
  Field f(5, 3);  // nx = 5, ny = 3: stored as shape (3, 5)
  for (Eigen::Index j = 0; j < 3; ++j)
    for (Eigen::Index i = 0; i < 5; ++i)
      f(i, j) = 10.0 * static_cast<double>(j) + static_cast<double>(i) + 0.25;
  coatfft::cli::write_npy(scratch("round.npy"), f);
  CHECK(fs::file_size(scratch("round.npy")) % 64 == (15 * 8) % 64);  // header padded to 64 bytes
  const Field g = coatfft::cli::read_npy(scratch("round.npy"));
  REQUIRE(g.rows() == 5);
  REQUIRE(g.cols() == 3);
  CHECK((g == f).all());
}

TEST_CASE("npy: reads NumPy's own header layout, row j is y_j", "[cli][npy]") {
  const auto path = npy_with_header(
      "numpy.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", 12);
  const Field f = coatfft::cli::read_npy(path);
  REQUIRE(f.rows() == 4);  // nx = columns of the (ny, nx) array
  REQUIRE(f.cols() == 3);
  CHECK(f(1, 0) == 1.0);  // C order: the second value is row 0, column 1
  CHECK(f(0, 1) == 4.0);
}

TEST_CASE("npy: refuses what it cannot read, naming the file", "[cli][npy][bad_input]") {
  using Catch::Contains;
  CHECK_THROWS_WITH(
      coatfft::cli::read_npy(npy_with_header(
          "int.npy", "{'descr': '<i4', 'fortran_order': False, 'shape': (3, 4), }", 6)),
      Contains("int.npy") && Contains("float64"));
  CHECK_THROWS_WITH(
      coatfft::cli::read_npy(npy_with_header(
          "fortran.npy", "{'descr': '<f8', 'fortran_order': True, 'shape': (3, 4), }", 12)),
      Contains("C order"));
  CHECK_THROWS_WITH(
      coatfft::cli::read_npy(npy_with_header(
          "vector.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", 3)),
      Contains("2-D"));
  CHECK_THROWS_WITH(
      coatfft::cli::read_npy(npy_with_header(
          "short.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", 5)),
      Contains("truncated"));
  std::ofstream(scratch("text.npy")) << "not an npy file at all";
  CHECK_THROWS_WITH(coatfft::cli::read_npy(scratch("text.npy")), Contains("not a .npy"));
  CHECK_THROWS_WITH(coatfft::cli::read_npy(scratch("missing.npy")), Contains("missing.npy"));
}

TEST_CASE("CSV matrix: comments, blanks and commas; ragged rows and words refused",
          "[cli][npy][bad_input]") {
  std::ofstream(scratch("good.csv")) << "# heights\n1, 2 3\n\n4,5,6  # row 1\n";
  const Field f = coatfft::cli::read_csv_matrix(scratch("good.csv"));
  REQUIRE(f.rows() == 3);
  REQUIRE(f.cols() == 2);
  CHECK(f(2, 1) == 6.0);
  std::ofstream(scratch("ragged.csv")) << "1,2,3\n4,5\n";
  CHECK_THROWS_WITH(coatfft::cli::read_csv_matrix(scratch("ragged.csv")),
                    Catch::Contains("ragged.csv:2"));
  std::ofstream(scratch("word.csv")) << "1,two,3\n";
  CHECK_THROWS_WITH(coatfft::cli::read_csv_matrix(scratch("word.csv")), Catch::Contains("\"two\""));
}
