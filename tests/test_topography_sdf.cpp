// The SDF reader (ISO 25178-71) on files written here byte by byte, in both variants, and on
// one file exported by another program (tests/data/topography/README.md).
#include <unistd.h>

#include <atomic>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "topography/formats.hpp"
#include "topography_files.hpp"

namespace {

namespace fs = std::filesystem;
using coatfft::topography::read_sdf_topography;
using coatfft::topography::Topography;

using coatfft::testing::append;
using coatfft::testing::memory_limit;
using coatfft::testing::metadata_value;
using coatfft::testing::size_limit;
using coatfft::testing::TempDir;

std::string header(int data_type, int nx = 4, int ny = 3, const std::string& extra = "") {
  return "aISO-1.0\r\n"
         "ManufacID   = coatfft\r\n"
         "CreateDate  = 010220241200\r\n"
         "ModDate     = 010220241300\r\n"
         "NumPoints   = " +
         std::to_string(nx) + "\r\nNumProfiles = " + std::to_string(ny) +
         "\r\n"
         "Xscale      = 1.0e-6\r\n"
         "Yscale      = 2.5E-6\r\n"
         "Zscale      = 1e-9\r\n"
         "Zresolution = -1\r\n"
         "Compression = 0\r\n"
         "DataType    = " +
         std::to_string(data_type) + "\r\nCheckType   = 0\r\n" + extra + "*\r\n";
}

// The reference map: value i + 10 j at point (i, j), nx = 4 != ny = 3, one profile a line.
std::string reference_values() {
  std::string data;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) data += std::to_string(i + 10 * j) + (i < 3 ? " " : "\r\n");
  }
  return data;
}

void check_reference_map(const Topography& topography) {
  CHECK(topography.format == "sdf");
  CHECK(topography.unit == "m");
  REQUIRE(topography.heights.rows() == 4);
  REQUIRE(topography.heights.cols() == 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      CHECK(topography.heights(i, j) == Approx(1e-9 * (i + 10 * j)).epsilon(1e-14));
  REQUIRE(topography.lx);
  REQUIRE(topography.ly);
  CHECK(*topography.lx == Approx(4e-6).epsilon(1e-14));    // NumPoints * Xscale
  CHECK(*topography.ly == Approx(7.5e-6).epsilon(1e-14));  // NumProfiles * Yscale
}

// ISO 25178-71's 81-byte binary header.
std::string binary_header(int data_type, std::uint16_t nx, std::uint16_t ny) {
  std::string bytes = "bISO-1.0";
  bytes += std::string("coatfft") + std::string(3, ' ');  // ManufacID, 10 bytes
  bytes += "010220241200";                                // CreateDate
  bytes += "010220241300";                                // ModDate
  append(bytes, nx);
  append(bytes, ny);
  for (const double scale : {1.0e-6, 2.5e-6, 1e-9, -1.0}) append(bytes, scale);
  bytes += std::string{0, static_cast<char>(data_type), 0};  // Compression, DataType, CheckType
  REQUIRE(bytes.size() == 81);
  return bytes;
}

}  // namespace

TEST_CASE("sdf: an ASCII map is read in place, with its size and metadata", "[topography][sdf]") {
  const TempDir dir;
  SECTION("DataType 7 (DOUBLE), the data section ended by * and a trailer") {
    const Topography topography = read_sdf_topography(
        dir.write(header(7) + reference_values() + "*\r\nOperator = A. Tester\r\n*\r\n"),
        size_limit(1 << 20));
    check_reference_map(topography);
    CHECK(topography.missing == 0);
    CHECK(metadata_value(topography, "version") == "aISO-1.0");
    CHECK(metadata_value(topography, "ManufacID") == "coatfft");
    CHECK(metadata_value(topography, "CreateDate") == "010220241200");
    CHECK(metadata_value(topography, "trailer") == "Operator = A. Tester");
    // Sq of 1e-9 (i + 10 j): the variances of i over 0..3 (5/4) and of 10 j over 0..2 (200/3).
    const auto& h = topography.heights;
    CHECK(std::sqrt((h - h.mean()).square().mean()) == Approx(1e-9 * std::sqrt(1.25 + 200.0 / 3)));
  }
  SECTION("the BCR dialect, LF line ends, comments, no final *") {
    std::string text = header(5, 4, 3, "; a comment\r\nNumDataSet = 1\r\n") + reference_values();
    text.replace(0, 8, "aBCR-1.0");
    std::erase(text, '\r');
    const Topography topography = read_sdf_topography(dir.write(text), size_limit(1 << 20));
    check_reference_map(topography);
    CHECK(metadata_value(topography, "NumDataSet") == "1");
  }
}

TEST_CASE("sdf: every data type, and the value each reserves for a missing point",
          "[topography][sdf]") {
  const TempDir dir;
  // DataType, a value in range, its missing-point mark ("" where the type has none).
  const struct {
    int code;
    std::string value, bad;
  } cases[] = {
      {0, "255", ""},
      {1, "65534", "65535"},
      {2, "4294967294", "4294967295"},
      {3, "-2.5e3", "-3.40282347e+38"},
      {4, "-127", "-128"},
      {5, "-32767", "-32768"},
      {6, "-2147483647", "-2147483648"},
      {7, "1.25e-3", "-1.79769313486232e+308"},  // -DBL_MAX to 15 digits: overflows to -inf
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION("DataType " << c.code) {
      // Values: 3 at (0, 0), c.value at (1, 0), a mark or 0 at (0, 1), "BAD" at (1, 1).
      const std::string bad = c.bad.empty() ? "0" : c.bad;
      const Topography topography = read_sdf_topography(
          dir.write(header(c.code, 2, 2) + "3 " + c.value + "\r\n" + bad + " BAD\r\n*\r\n"),
          size_limit(1 << 20));
      CHECK(topography.heights(0, 0) == Approx(3e-9));
      CHECK(topography.heights(1, 0) == Approx(std::stod(c.value) * 1e-9));
      CHECK(std::isnan(topography.heights(1, 1)));
      CHECK(std::isnan(topography.heights(0, 1)) == !c.bad.empty());
      CHECK(topography.missing == (c.bad.empty() ? 1u : 2u));
    }
  }
  SECTION("NaN in a floating-point map, and -DBL_MAX written in full") {
    const Topography topography = read_sdf_topography(
        dir.write(header(7, 2, 1) + "nan -1.7976931348623157e+308\r\n*\r\n"), size_limit(1 << 20));
    CHECK(topography.missing == 2);
  }
}

TEST_CASE("sdf: the binary variant", "[topography][sdf]") {
  const TempDir dir;
  std::string bytes = binary_header(5, 4, 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) append(bytes, static_cast<std::int16_t>(i + 10 * j));
  SECTION("INT16 values, then a trailer") {
    const Topography topography =
        read_sdf_topography(dir.write(bytes + "Operator = A. Tester\r\n"), size_limit(1 << 20));
    check_reference_map(topography);
    CHECK(topography.missing == 0);
    CHECK(metadata_value(topography, "version") == "bISO-1.0");
    CHECK(metadata_value(topography, "ManufacID") == "coatfft");
    CHECK(metadata_value(topography, "trailer") == "Operator = A. Tester");
  }
  SECTION("a negative value and the missing-point mark") {
    bytes[81] = '\xFF';  // (0, 0): -1
    bytes[82] = '\xFF';
    bytes[83] = '\x00';  // (1, 0): -32768, the mark
    bytes[84] = '\x80';
    const Topography topography = read_sdf_topography(dir.write(bytes), size_limit(1 << 20));
    CHECK(topography.heights(0, 0) == Approx(-1e-9));
    CHECK(std::isnan(topography.heights(1, 0)));
    CHECK(topography.missing == 1);
  }
  SECTION("DOUBLE values") {
    std::string doubles = binary_header(7, 2, 1);
    append(doubles, 4.5);
    append(doubles, -7.25);
    const Topography topography = read_sdf_topography(dir.write(doubles), size_limit(1 << 20));
    CHECK(topography.heights(0, 0) == Approx(4.5e-9));
    CHECK(topography.heights(1, 0) == Approx(-7.25e-9));
  }
  SECTION("truncated data") {
    bytes.resize(bytes.size() - 1);
    const fs::path path = dir.write(bytes);
    CHECK_THROWS_WITH(read_sdf_topography(path, size_limit(1 << 20)),
                      Catch::StartsWith(path.string() + ": the data section holds 23 bytes") &&
                          Catch::Contains("take 24 (truncated)"));
  }
  SECTION("a truncated header") {
    const fs::path path = dir.write(bytes.substr(0, 50));
    CHECK_THROWS_WITH(read_sdf_topography(path, size_limit(1 << 20)),
                      Catch::Contains("50 bytes, fewer than the 81 of the binary header"));
  }
}

TEST_CASE("sdf: malformed files are refused by name", "[topography][sdf]") {
  const TempDir dir;
  const auto refused = [&](const std::string& content, const std::string& what) {
    const fs::path path = dir.write(content);
    CHECK_THROWS_AS(read_sdf_topography(path, size_limit(1 << 20)), coatfft::InvalidArgument);
    CHECK_THROWS_WITH(read_sdf_topography(path, size_limit(1 << 20)),
                      Catch::StartsWith(path.string() + ": ") && Catch::Contains(what));
  };
  const std::string good = header(7) + reference_values() + "*\r\n";
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  SECTION("too few values (truncated)") {
    refused(header(7) + "0 1 2 3\r\n10 11\r\n",
            "the data section holds 6 values, but NumPoints * NumProfiles = 4 * 3 = 12 "
            "(truncated)");
  }
  SECTION("a wrong point count") {
    refused(with("NumPoints   = 4", "NumPoints   = 3"),
            "the data section holds more than NumPoints * NumProfiles = 3 * 3 values");
    refused(with("NumProfiles = 3", "NumProfiles = 4"),
            "the data section holds 12 values, but NumPoints * NumProfiles = 4 * 4 = 16");
  }
  SECTION("bad keyword values") {
    refused(with("NumPoints   = 4", "NumPoints   = four"),
            "NumPoints = \"four\" is not an integer");
    refused(with("NumPoints   = 4", "NumPoints   = 0"), "NumPoints = 0, but it must be >= 1");
    refused(with("Xscale      = 1.0e-6", "Xscale      = -1e-6"),
            "Xscale = -1e-06, but a scale must be > 0");
    refused(with("Zscale      = 1e-9", "Zscale      = 1nm"), "Zscale = \"1nm\" is not a number");
    refused(with("DataType    = 7", "DataType    = 9"),
            "DataType = 9 is not a data type of ISO 25178-71 or BCR (0 to 7)");
    refused(with("Compression = 0", "Compression = 1"), "compressed data are not read");
    refused(with("CheckType   = 0", "CheckType   = 1"), "checksummed data are not read");
  }
  SECTION("a missing or repeated keyword") {
    refused(with("Yscale      = 2.5E-6\r\n", ""), "the header has no Yscale");
    refused(with("Yscale      = 2.5E-6\r\n", "Yscale = 1\r\nyscale = 2\r\n"),
            "the header names yscale twice");
  }
  SECTION("a header without its end") {
    refused(header(7).substr(0, header(7).size() - 3),
            "the header does not end with a line \"*\" (truncated)");
  }
  SECTION("values that do not fit the data type") {
    refused(header(5) + "0 1 2 40000\r\n",
            "value 4 of the data section, \"40000\", is not an "
            "integer of DataType 5 (INT16)");
    refused(header(6) + "0 1.5\r\n", "value 2 of the data section, \"1.5\", is not an integer");
    refused(header(7) + "0 1 x\r\n", "value 3 of the data section, \"x\", is not a number");
  }
  SECTION("not an SDF file") {
    refused("NumPoints = 4\r\n", "not an SDF file: it starts with \"NumPoint\"");
    refused("", "not an SDF file");
  }
  SECTION("more points than the limit allows") {
    const fs::path path = dir.write(header(7, 100000, 100000));
    CHECK_THROWS_WITH(read_sdf_topography(path, size_limit(1 << 20)),
                      Catch::Contains("NumPoints * NumProfiles = 100000 * 100000 points, more "
                                      "than the limit of 131072 points"));
  }
}

TEST_CASE("sdf: a MountainsMap 11 export (ASCII, INT32, one point not measured)",
          "[topography][sdf]") {
  const fs::path path =
      fs::path(COATFFT_SOURCE_DIR) / "tests/data/topography/mm11_iso1_ascii_int32.sdf";
  const Topography topography = read_sdf_topography(path, size_limit(1 << 20));
  REQUIRE(topography.heights.rows() == 30);
  REQUIRE(topography.heights.cols() == 20);
  CHECK(*topography.lx == Approx(30e-6));
  CHECK(*topography.ly == Approx(20e-6));
  CHECK(topography.missing == 1);
  CHECK(std::isnan(topography.heights(29, 0)));
  // 100000 (i + 30 j) times Zscale 1e-14 m.
  CHECK(topography.heights(0, 0) == 0);
  CHECK(topography.heights(28, 0) == Approx(28e-9));
  CHECK(topography.heights(0, 1) == Approx(30e-9));
  CHECK(topography.heights(29, 19) == Approx(599e-9));
  CHECK(topography.heights(7, 11) == Approx(337e-9));
  CHECK(metadata_value(topography, "ManufacID") == "test");
}

// A header declaring far more points than the data section holds, read in a child process whose
// memory may grow by 16 MiB (the 23000 x 23000 map would take 4.2 GB): the values are counted
// before the map is allocated.
TEST_CASE("sdf: NumPoints * NumProfiles beyond the values held is refused before allocating",
          "[topography][sdf]") {
  const TempDir dir;
  const fs::path path = dir.write(header(7, 23000, 23000) + "1 2 3\r\n*\r\n");
  const auto run = coatfft::testing::run_bounded(std::uintmax_t{16} << 20, 5, [&] {
    // The memory check passes: what the file holds must refuse it.
    (void)read_sdf_topography(path, memory_limit(1e12));
  });
  CHECK(run.outcome == path.string() +
                           ": the data section holds 3 values, but NumPoints * NumProfiles = "
                           "23000 * 23000 = 529000000 (truncated)");
  CHECK(run.seconds < 5);
}

// 2^20 values (an 8 MiB map) within 13 MiB more memory: the map is held once (the values read
// and the heights made of them are the same array; a binary file's values are read from the file
// piece by piece, not held whole beside the map).
TEST_CASE("sdf: a map is held once", "[topography][sdf]") {
  const TempDir dir;
  const auto read_within = [](const fs::path& path, double last) {
    return coatfft::testing::run_bounded(std::uintmax_t{13} << 20, 5, [&] {
      const Topography topography = read_sdf_topography(path, {});
      if (topography.missing != 1 || topography.heights(1023, 1023) != last)
        throw std::runtime_error("wrong values");
    });
  };
  SECTION("ASCII, 2 MiB of text") {
    std::string values;
    for (int k = 0; k < 1024 * 1024; ++k) values += k == 5 ? "BAD " : "2 ";
    const fs::path path = dir.write(header(7, 1024, 1024) + values + "*\r\n");
    CHECK(read_within(path, 2e-9).outcome == "returned");
  }
  SECTION("binary DOUBLE, 8 MiB of values") {
    std::string bytes = binary_header(7, 1024, 1024);
    for (int k = 0; k < 1024 * 1024; ++k)
      append(bytes, k == 5 ? std::numeric_limits<double>::quiet_NaN() : 2.0);
    const fs::path path = dir.write(bytes);
    CHECK(read_within(path, 2e-9).outcome == "returned");
  }
}
