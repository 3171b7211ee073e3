// The scene layer's .npy and CSV readers and writers, and the checks on input files they share.
#include <sys/stat.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"
#include "io/npy.hpp"

namespace fs = std::filesystem;
using coatfft::Field;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_scene_reader_tests";
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

TEST_CASE("npy: write then read round-trips shape and values", "[scene][npy]") {
  Field f(5, 3);  // nx = 5, ny = 3: stored as shape (3, 5)
  for (Eigen::Index j = 0; j < 3; ++j)
    for (Eigen::Index i = 0; i < 5; ++i)
      f(i, j) = 10.0 * static_cast<double>(j) + static_cast<double>(i) + 0.25;
  coatfft::io::write_npy(scratch("round.npy"), f);
  CHECK(fs::file_size(scratch("round.npy")) % 64 == (15 * 8) % 64);  // header padded to 64 bytes
  const Field g = coatfft::io::read_npy(scratch("round.npy"));
  REQUIRE(g.rows() == 5);
  REQUIRE(g.cols() == 3);
  CHECK((g == f).all());
}

TEST_CASE("npy: reads NumPy's own header layout, row j is y_j", "[scene][npy]") {
  const auto path = npy_with_header(
      "numpy.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", 12);
  const Field f = coatfft::io::read_npy(path);
  REQUIRE(f.rows() == 4);  // nx = columns of the (ny, nx) array
  REQUIRE(f.cols() == 3);
  CHECK(f(1, 0) == 1.0);  // C order: the second value is row 0, column 1
  CHECK(f(0, 1) == 4.0);
}

TEST_CASE("npy: float32 and big-endian values, Fortran order: the same array", "[scene][npy]") {
  // The (3, 4) array a[r, c] = 4 r + c + 0.5 (exact in float32) written in each layout numpy
  // exports: the bytes made here independently of the reader.
  const auto write = [](const std::string& name, const std::string& descr, bool fortran) {
    const bool big = descr[0] == '>';
    const std::size_t size = descr[2] == '4' ? 4 : descr[2] == '2' ? 2 : 8;
    std::string data;
    for (int k = 0; k < 12; ++k) {
      const int r = fortran ? k % 3 : k / 4, c = fortran ? k / 3 : k % 4;
      const double v = 4.0 * r + c + 0.5;
      unsigned char b[8];
      if (size == 4) {
        const float f = static_cast<float>(v);
        std::memcpy(b, &f, 4);
      } else if (size == 2) {
        // IEEE binary16 by its definition: v = 2^e (1 + m/1024), bits (e + 15) << 10 | m
        // (every value here, 0.5 to 11.5, is exact in it).
        const int e = static_cast<int>(std::floor(std::log2(v)));
        const auto m = static_cast<std::uint16_t>(std::lround((v / std::ldexp(1.0, e) - 1) * 1024));
        const auto bits = static_cast<std::uint16_t>((e + 15) << 10 | m);
        std::memcpy(b, &bits, 2);
      } else {
        std::memcpy(b, &v, 8);
      }
      if (big) std::reverse(b, b + size);
      data.append(reinterpret_cast<const char*>(b), size);
    }
    const std::string header = "{'descr': '" + descr +
                               "', 'fortran_order': " + (fortran ? "True" : "False") +
                               ", 'shape': (3, 4), }";
    const fs::path path = scratch(name);
    std::ofstream out(path, std::ios::binary);
    out.write("\x93NUMPY\x01\x00", 8);
    out.put(static_cast<char>(header.size()));
    out.put('\0');
    out << header << data;
    return path;
  };
  for (const char* descr : {"<f8", ">f8", "<f4", ">f4", "=f4", "<f2", ">f2"})
    for (bool fortran : {false, true}) {
      INFO(descr << (fortran ? " Fortran" : " C"));
      const Field f = coatfft::io::read_npy(write("layout.npy", descr, fortran));
      REQUIRE(f.rows() == 4);
      REQUIRE(f.cols() == 3);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) CHECK(f(c, r) == 4.0 * r + c + 0.5);
    }
}

TEST_CASE("npy: refuses what it cannot read, naming the file", "[scene][npy][bad_input]") {
  using Catch::Contains;
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(npy_with_header(
          "int.npy", "{'descr': '<i4', 'fortran_order': False, 'shape': (3, 4), }", 6)),
      Contains("int.npy") && Contains("float64, float32 or float16"));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(npy_with_header(
          "quad.npy", "{'descr': '<f16', 'fortran_order': False, 'shape': (3, 4), }", 3)),
      Contains("float64, float32 or float16"));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(npy_with_header(
          "order.npy", "{'descr': '<f8', 'fortran_order': 1, 'shape': (3, 4), }", 12)),
      Contains("fortran_order"));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(npy_with_header(
          "vector.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", 3)),
      Contains("2-D"));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(npy_with_header(
          "short.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", 5)),
      Contains("truncated"));
  std::ofstream(scratch("text.npy")) << "not an npy file at all";
  CHECK_THROWS_WITH(coatfft::io::read_npy(scratch("text.npy")), Contains("not a .npy"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(scratch("missing.npy")), Contains("missing.npy"));
}

TEST_CASE("CSV matrix: a spreadsheet's byte order mark and header lines, tabs", "[scene][npy]") {
  std::ofstream(scratch("export.csv")) << "\xEF\xBB\xBF"
                                       << "x;y;Height [nm]\nunit: nm\n"
                                       << "1\t2\t3\n4\t5\t6\n";
  const Field f = coatfft::io::read_csv_matrix(scratch("export.csv"));
  REQUIRE(f.rows() == 3);
  REQUIRE(f.cols() == 2);
  CHECK(f(0, 0) == 1.0);
  CHECK(f(2, 1) == 6.0);
  // A first row with a typo among numbers is a row, not a header: refused, named.
  std::ofstream(scratch("typo.csv")) << "1, tw0, 3\n4, 5, 6\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("typo.csv")),
                    Catch::Contains("typo.csv:1") && Catch::Contains("\"tw0\""));
  // Words after the first row are not a header.
  std::ofstream(scratch("late.csv")) << "1, 2\nx, y\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("late.csv")),
                    Catch::Contains("late.csv:2"));
  // A file of headers alone has no data.
  std::ofstream(scratch("words.csv")) << "\xEF\xBB\xBFx, y\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("words.csv")), Catch::Contains("no data"));
}

TEST_CASE("CSV matrix: comments, blanks and commas; ragged rows and words refused",
          "[scene][npy][bad_input]") {
  std::ofstream(scratch("good.csv")) << "# heights\n1, 2 3\n\n4,5,6  # row 1\n";
  const Field f = coatfft::io::read_csv_matrix(scratch("good.csv"));
  REQUIRE(f.rows() == 3);
  REQUIRE(f.cols() == 2);
  CHECK(f(2, 1) == 6.0);
  std::ofstream(scratch("ragged.csv")) << "1,2,3\n4,5\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("ragged.csv")),
                    Catch::Contains("ragged.csv:2"));
  std::ofstream(scratch("word.csv")) << "1,two,3\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("word.csv")), Catch::Contains("\"two\""));
}

namespace {

// A .npy file of version `major` (1: 2-byte header length, 2 and 3: 4-byte) holding `header`
// as it is (no padding added) followed by `data_bytes` zero bytes.
fs::path raw_npy(const std::string& name, int major, const std::string& header,
                 std::size_t data_bytes) {
  const fs::path path = scratch(name);
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY", 6);
  out.put(static_cast<char>(major));
  out.put('\0');
  const int length_bytes = major == 1 ? 2 : 4;
  for (int k = 0; k < length_bytes; ++k) out.put(static_cast<char>(header.size() >> (8 * k)));
  out << header << std::string(data_bytes, '\0');
  return path;
}

// A FIFO with no writer: opening it for reading the ordinary way would block.
fs::path fifo(const std::string& name) {
  const fs::path path = scratch(name);
  fs::remove(path);
  REQUIRE(::mkfifo(path.c_str(), 0600) == 0);
  return path;
}

fs::path symlink_to(const std::string& name, const fs::path& target) {
  const fs::path path = scratch(name);
  fs::remove(path);
  fs::create_symlink(target, path);
  return path;
}

std::string message_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const coatfft::InvalidArgument& e) {
    return e.what();
  }
  FAIL("no InvalidArgument thrown");
  return "";
}

}  // namespace

TEST_CASE("input files: only regular files are opened, sizes are checked first",
          "[scene][npy][bad_input]") {
  using Catch::Contains;
  using coatfft::io::read_input_file;
  std::ofstream(scratch("input.txt")) << "hello\n";
  CHECK(coatfft::io::read_input_file(scratch("input.txt"), "a test file", 100) == "hello\n");
  CHECK(coatfft::io::read_input_file(scratch("input.txt"), "a test file", 6) == "hello\n");
  CHECK_THROWS_WITH(coatfft::io::read_input_file(scratch("input.txt"), "a test file", 5),
                    Contains("input.txt: 6 bytes, more than the limit of 5 bytes for a test file"));
  CHECK_THROWS_WITH(coatfft::io::read_input_file(scratch("absent.txt"), "a test file", 100),
                    Contains("absent.txt: cannot open: No such file or directory"));
  fs::create_directories(scratch("a_directory"));
  CHECK_THROWS_WITH(coatfft::io::read_input_file(scratch("a_directory"), "a test file", 100),
                    Contains("a_directory: not a regular file (a directory)"));
  CHECK_THROWS_WITH(coatfft::io::read_input_file(fifo("input.fifo"), "a test file", 100),
                    Contains("input.fifo: not a regular file (a FIFO)"));
  CHECK_THROWS_WITH(
      coatfft::io::read_input_file(symlink_to("zero.txt", "/dev/zero"), "a test file", 1u << 30),
      Contains("zero.txt: not a regular file (a character device)"));
  CHECK(coatfft::io::read_input_file(symlink_to("link.txt", scratch("input.txt")), "a test file",
                                     100) == "hello\n");
  CHECK(coatfft::io::require_regular_input(scratch("input.txt"), "a test file", 100) == 6);
  coatfft::io::InputFile file(scratch("input.txt"), "a test file", 100);
  char bytes[4] = {};
  file.read_exact(bytes, 4);
  CHECK(std::string(bytes, 4) == "hell");
  CHECK_THROWS_WITH(file.read_exact(bytes, 4), Contains("changed while being read"));
}

TEST_CASE("npy and CSV: FIFOs, directories and devices are refused without blocking",
          "[scene][npy][bad_input]") {
  using Catch::Contains;
  using coatfft::io::read_csv_matrix;
  using coatfft::io::read_npy;
  CHECK_THROWS_WITH(coatfft::io::read_npy(fifo("pipe.npy")),
                    Contains("pipe.npy: not a regular file (a FIFO)"));
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(fifo("pipe.csv")),
                    Contains("pipe.csv: not a regular file (a FIFO)"));
  fs::create_directories(scratch("dir.npy"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(scratch("dir.npy")), Contains("(a directory)"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(symlink_to("zero.npy", "/dev/zero")),
                    Contains("zero.npy: not a regular file (a character device)"));
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(symlink_to("zero.csv", "/dev/zero")),
                    Contains("zero.csv: not a regular file (a character device)"));
  std::ofstream(scratch("limit.csv")) << "1, 2, 3\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("limit.csv"), 4),
                    Contains("8 bytes, more than the limit of 4 bytes for a CSV file"));
}

TEST_CASE("npy: sizes in the header are checked against the file before allocating",
          "[scene][npy][bad_input]") {
  using Catch::Contains;
  using coatfft::io::read_npy;
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': ";
  // 60000 x 60000 doubles would take 28.8 GB: refused from the sizes alone, quickly.
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(coatfft::io::read_npy(raw_npy("huge.npy", 1, dict + "(60000, 60000), }\n", 16)),
                    Contains("huge.npy: truncated data: shape \"(60000, 60000)\" needs "
                             "28800000000 bytes") &&
                        Contains("the file has 16"));
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(raw_npy("overflow.npy", 1, dict + "(4294967296, 4294967296), }", 8)),
      Contains("needs more than 2^64 bytes"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(raw_npy(
                        "digits.npy", 1, dict + "(123456789012345678901234567890, 1), }", 8)),
                    Contains("truncated data") && Contains("123456789012345678901234567890"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(raw_npy("trailing.npy", 1, dict + "(1, 2), }", 24)),
                    Contains("needs 16 bytes") && Contains("the file has 24"));
  // A header length beyond the end of the file, and beyond the limit on headers.
  const fs::path cut = raw_npy("cutheader.npy", 1, dict, 0);
  fs::resize_file(cut, 20);
  CHECK_THROWS_WITH(coatfft::io::read_npy(cut), Contains("cutheader.npy: truncated .npy header"));
  std::ofstream(scratch("bighead.npy"), std::ios::binary)
      << std::string("\x93NUMPY\x02\x00\xff\xff\xff\x7f", 12) << "{";
  CHECK_THROWS_WITH(coatfft::io::read_npy(scratch("bighead.npy")),
                    Contains(".npy header of 2147483647 bytes, more than the limit"));
}

TEST_CASE("npy: the header is parsed strictly and quoted as it is in the file",
          "[scene][npy][bad_input]") {
  using Catch::Contains;
  using coatfft::io::read_npy;
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': ";
  const std::string blanks_msg = message_of([&] {
    coatfft::io::read_npy(raw_npy("blanks.npy", 1, dict + "(32 32 ), }" + std::string(40, ' '), 0));
  });
  CHECK_THAT(blanks_msg, Contains("2-D") && Contains("shape is \"(32 32 )\"") &&
                             Contains("header \"" + dict + "(32 32 ), }\""));
  CHECK_THAT(blanks_msg, !Contains("(32, 2)"));
  for (const std::string shape :
       {"(3,)", "()", "(3, 4, 5)", "(0, 4)", "(3, -4)", "(3, 4.0)", "(3,, 4)", "(+3, 4)", "(3 4,)"})
    CHECK_THROWS_WITH(coatfft::io::read_npy(raw_npy("shape.npy", 1, dict + shape + ", }", 96)),
                      Contains("2-D") && Contains("\"" + shape + "\""));
  // Blanks and a trailing comma are fine, and so is a version 2.0 header with double quotes.
  CHECK(coatfft::io::read_npy(raw_npy("spaced.npy", 1, dict + "( 3 ,4 , ), }\n", 96)).size() == 12);
  CHECK(coatfft::io::read_npy(
            raw_npy("v2.npy", 2,
                    "{\"descr\": \"<f8\", \"fortran_order\": False, \"shape\": (2, 2)}", 32))
            .size() == 4);
  const std::string binary_msg = message_of(
      [&] { coatfft::io::read_npy(raw_npy("binary.npy", 1, "{'descr': '<f8'\x01\xff\"\\", 0)); });
  CHECK_THAT(binary_msg, Contains("malformed .npy header") &&
                             Contains("\"{'descr': '<f8'\\x01\\xff\\\"\\\\\""));
  // Shortened to 80 characters without cutting an escape in two.
  const std::string cut_msg = message_of([&] {
    coatfft::io::read_npy(raw_npy("cut.npy", 1, "{'descr': '<f8'" + std::string(70, '\x01'), 0));
  });
  CHECK_THAT(cut_msg,
             Contains("'<f8'\\x01\\x01") && Contains("\\x01...\"") && !Contains("\\x0..."));
  const std::string long_msg = message_of([&] {
    coatfft::io::read_npy(raw_npy("long.npy", 1, dict + "(3, 4), 'x" + std::string(5000, 'y'), 0));
  });
  CHECK_THAT(long_msg, Contains("...\"") && Contains("malformed .npy header"));
  CHECK(long_msg.size() < 200);
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(raw_npy("unknown.npy", 1, dict + "(1, 1), 'extra': 1}", 8)),
      Contains("unknown key"));
  CHECK_THROWS_WITH(
      coatfft::io::read_npy(raw_npy("twice.npy", 1, dict + "(1, 1), 'shape': (1, 1)}", 8)),
      Contains("duplicate key"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(
                        raw_npy("noshape.npy", 1, "{'descr': '<f8', 'fortran_order': False}", 8)),
                    Contains("is missing"));
  CHECK_THROWS_WITH(coatfft::io::read_npy(raw_npy("after.npy", 1, dict + "(1, 1)} x", 8)),
                    Contains("after the closing"));
}

TEST_CASE("CSV matrix: float64 range, 1-based line numbers, 0-based rows and columns",
          "[scene][npy][bad_input]") {
  using Catch::Contains;
  using coatfft::io::read_csv_matrix;
  std::ofstream(scratch("tiny.csv")) << "1e-400, -1e-400, 1e-310, +2.5\n4.9e-324, inf, -0, 7\n";
  const Field f = coatfft::io::read_csv_matrix(scratch("tiny.csv"));
  REQUIRE(f.rows() == 4);
  REQUIRE(f.cols() == 2);
  CHECK(f(0, 0) == 0.0);  // underflow: the IEEE value strtod gives, as numpy.loadtxt reads it
  CHECK(std::signbit(f(1, 0)));
  CHECK(f(2, 0) == 1e-310);  // a subnormal
  CHECK(std::fpclassify(f(2, 0)) == FP_SUBNORMAL);
  CHECK(f(3, 0) == 2.5);
  CHECK(f(0, 1) == std::numeric_limits<double>::denorm_min());
  CHECK(std::isinf(f(1, 1)));

  std::ofstream(scratch("big.csv")) << "# header\n\n1, 2\n3, -1e400\n";
  const std::string big_msg = message_of([] { coatfft::io::read_csv_matrix(scratch("big.csv")); });
  CHECK(big_msg == scratch("big.csv").string() +
                       ":4: row 1, column 1: \"-1e400\" is out of the range of float64");
  std::ofstream(scratch("words.csv")) << "1 2 3\n# comment\n4 5 x6\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("words.csv")),
                    Contains("words.csv:3: row 1, column 2: \"x6\" is not a number"));
  std::ofstream(scratch("ragged2.csv")) << "\n1,2,3\n4,5,6\n\n7,8\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("ragged2.csv")),
                    Contains("ragged2.csv:5: row 2 has 2 columns, row 0 (line 2) has 3"));
  for (const char* bad : {"+", "+-1", "++1", "0x10", "1e", "5.5.5", "nan()x"}) {
    std::ofstream(scratch("bad.csv")) << "1 " << bad << "\n";
    CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("bad.csv")),
                      Contains("bad.csv:1: row 0, column 1: \"") && Contains("is not a number"));
  }
  std::ofstream(scratch("long.csv")) << "1, " << std::string(5000, '7') << "x\n";
  const std::string long_msg =
      message_of([] { coatfft::io::read_csv_matrix(scratch("long.csv")); });
  CHECK_THAT(long_msg, Contains("long.csv:1: row 0, column 1: \"777") && Contains("...\""));
  CHECK(long_msg.size() < 200);
  std::ofstream(scratch("nul.csv"), std::ios::binary) << std::string("1\0", 2) << "\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("nul.csv")),
                    Contains("\"1\\x00\" is not a number"));
  std::ofstream(scratch("empty.csv")) << "# nothing\n\n";
  CHECK_THROWS_WITH(coatfft::io::read_csv_matrix(scratch("empty.csv")),
                    Contains("empty.csv: no data"));
}
