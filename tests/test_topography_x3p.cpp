// The X3P reader (ISO 25178-72) on archives written here byte by byte: main.xml by hand, the
// point data laid out value by value in little endian, the zip by libzip's writing API and the
// checksums by Boost's MD5 (itself checked against RFC 1321's test vectors).
#include <unistd.h>
#include <zip.h>

#include <atomic>
#include <bit>
#include <boost/uuid/detail/md5.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "topography/formats.hpp"
#include "topography_files.hpp"

namespace {

namespace fs = std::filesystem;
using coatfft::topography::read_x3p_topography;
using coatfft::topography::Topography;

// Boost 1.74's MD5 digest: four words whose values read the digest's bytes high byte first.
std::string md5_hex(const std::string& bytes) {
  boost::uuids::detail::md5 hash;
  hash.process_bytes(bytes.data(), bytes.size());
  boost::uuids::detail::md5::digest_type digest;
  hash.get_digest(digest);
  std::string hex;
  for (const unsigned int word : digest)
    for (int shift = 28; shift >= 0; shift -= 4) hex += "0123456789abcdef"[(word >> shift) & 0xF];
  return hex;
}

using coatfft::testing::append;
using coatfft::testing::memory_limit;
using coatfft::testing::metadata_value;
using coatfft::testing::size_limit;
using coatfft::testing::TempDir;

using Entries = std::vector<std::pair<std::string, std::string>>;

// Entries deflated, or `stored` as they are (where a test damages their bytes in the file).
void write_zip(const fs::path& path, const Entries& entries, bool stored = false) {
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  REQUIRE(archive != nullptr);
  for (const auto& [name, content] : entries) {
    zip_source_t* source = zip_source_buffer(archive, content.data(), content.size(), 0);
    REQUIRE(source != nullptr);
    const zip_int64_t index = zip_file_add(archive, name.c_str(), source, ZIP_FL_OVERWRITE);
    REQUIRE(index >= 0);
    if (stored) REQUIRE(zip_set_file_compression(archive, index, ZIP_CM_STORE, 0) == 0);
  }
  REQUIRE(zip_close(archive) == 0);
}

// What goes into an archive; each field a test may spoil.
struct X3p {
  std::string data_type = "D";  // CZ/DataType
  std::string size_x = "4", size_y = "3", size_z = "1";
  std::string z_axis_extra;  // <Increment>, <Offset> of CZ
  std::string feature_type = "SUR";
  std::string x_axis_type = "I";
  std::string data;                            // bindata/data.bin
  std::optional<std::string> valid;            // bindata/valid.bin
  std::optional<std::string> data_checksum;    // MD5ChecksumPointData; md5(data) when unset
  bool with_data_checksum = true;              // false: no MD5ChecksumPointData (optional)
  bool stored = false;                         // entries stored, not deflated
  std::optional<std::string> record_checksum;  // md5checksum.hex; md5(main.xml) when unset
  std::string data_list;                       // inline <Datum> elements instead of a DataLink
  bool with_main = true;
};

std::string main_xml(const X3p& x3p) {
  std::string link;
  if (x3p.data_list.empty()) {
    link = "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>";
    if (x3p.with_data_checksum)
      link += "<MD5ChecksumPointData>" + x3p.data_checksum.value_or(md5_hex(x3p.data)) +
              "</MD5ChecksumPointData>";
    if (x3p.valid)
      link += "<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>" +
              md5_hex(*x3p.valid) + "</MD5ChecksumValidPoints>";
    link += "</DataLink>";
  } else {
    link = "<DataList>" + x3p.data_list + "</DataList>";
  }
  return R"(<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>)" +
         x3p.feature_type + R"(</FeatureType>
    <Axes>
      <CX><AxisType>)" +
         x3p.x_axis_type +
         R"(</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2.0E-6</Increment></CY>
      <CZ><AxisType>A</AxisType><DataType>)" +
         x3p.data_type + "</DataType>" + x3p.z_axis_extra + R"(</CZ>
    </Axes>
  </Record1>
  <Record2>
    <Date>2024-05-06T07:08:09+02:00</Date>
    <Creator>A. Tester</Creator>
    <Instrument><Manufacturer>Acme</Manufacturer><Model>Profiler 3000</Model>
      <Serial>42</Serial><Version>1.2</Version></Instrument>
    <CalibrationDate>2024-01-01T00:00:00+01:00</CalibrationDate>
    <ProbingSystem><Type>NonContacting</Type><Identification>50x</Identification></ProbingSystem>
    <Comment>written by hand</Comment>
  </Record2>
  <Record3>
    <MatrixDimension><SizeX>)" +
         x3p.size_x + "</SizeX><SizeY>" + x3p.size_y + "</SizeY><SizeZ>" + x3p.size_z +
         "</SizeZ></MatrixDimension>\n    " + link + R"(
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
)";
}

fs::path write_x3p(const TempDir& dir, const X3p& x3p, const std::string& name = "map.x3p") {
  const std::string xml = main_xml(x3p);
  Entries entries;
  if (x3p.with_main) entries.emplace_back("main.xml", xml);
  entries.emplace_back("md5checksum.hex",
                       x3p.record_checksum.value_or(md5_hex(xml)) + " *main.xml\n");
  if (x3p.data_list.empty()) entries.emplace_back("bindata/data.bin", x3p.data);
  if (x3p.valid) entries.emplace_back("bindata/valid.bin", *x3p.valid);
  const fs::path path = dir / name;
  write_zip(path, entries, x3p.stored);
  return path;
}

// The archive at `path` with the unpacked size of `entry` in its local and central headers
// replaced by `size`: a header that lies.
void declare_size(const fs::path& path, const std::string& entry, std::uint32_t size) {
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  int patched = 0;
  // Local header "PK\3\4": size at 22, name length at 26, name at 30; central "PK\1\2": 24,
  // 28, 46 (APPNOTE.TXT 4.3.7 and 4.3.12).
  for (const auto& [signature, at_size, at_length, at_name] :
       {std::tuple{std::string("PK\3\4", 4), 22, 26, 30},
        std::tuple{std::string("PK\1\2", 4), 24, 28, 46}})
    for (auto k = bytes.find(signature); k != std::string::npos; k = bytes.find(signature, k + 1)) {
      const std::size_t length = static_cast<unsigned char>(bytes[k + at_length]) +
                                 256U * static_cast<unsigned char>(bytes[k + at_length + 1]);
      if (bytes.compare(k + at_name, length, entry) != 0) continue;
      for (int b = 0; b < 4; ++b) bytes[k + at_size + b] = static_cast<char>(size >> (8 * b));
      ++patched;
    }
  REQUIRE(patched == 2);
  std::ofstream(path, std::ios::binary) << bytes;
}

// The reference map: distinct values at every point, nx != ny, so a transposed or mirrored
// read shows.
constexpr int kNx = 4, kNy = 3;
double reference_height(int i, int j) {
  return 1e-6 * (i + 10 * j);
}

std::string reference_doubles() {
  std::string data;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) append(data, reference_height(i, j));  // x fastest
  return data;
}

// Sq: the root mean square of the heights about their mean.
double rms_about_mean(const coatfft::Field& heights) {
  return std::sqrt((heights - heights.mean()).square().mean());
}

}  // namespace

TEST_CASE("the test's MD5 matches RFC 1321's test vectors", "[topography][x3p]") {
  CHECK(md5_hex("") == "d41d8cd98f00b204e9800998ecf8427e");
  CHECK(md5_hex("abc") == "900150983cd24fb0d6963f7d28e17f72");
  CHECK(md5_hex("message digest") == "f96b697d7cb7938d525a2f31aaf161d0");
}

TEST_CASE("x3p: double heights on a grid are read in place, with size and metadata",
          "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.data = reference_doubles();
  const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
  CHECK(topography.format == "x3p");
  CHECK(topography.unit == "m");
  REQUIRE(topography.heights.rows() == kNx);
  REQUIRE(topography.heights.cols() == kNy);
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) CHECK(topography.heights(i, j) == reference_height(i, j));
  CHECK(topography.heights(3, 0) ==
        Approx(3e-6).epsilon(1e-15));  // x along the file's fastest index
  CHECK(topography.heights(0, 2) == Approx(20e-6).epsilon(1e-15));
  REQUIRE(topography.lx);
  REQUIRE(topography.ly);
  CHECK(*topography.lx == Approx(4e-6).epsilon(1e-14));  // SizeX * Increment of CX
  CHECK(*topography.ly == Approx(6e-6).epsilon(1e-14));  // SizeY * Increment of CY
  // Sq of 1e-6 (i + 10 j): the variances of i over 0..3 (5/4) and of 10 j over 0..2 (200/3).
  CHECK(rms_about_mean(topography.heights) == Approx(1e-6 * std::sqrt(1.25 + 200.0 / 3)));
  CHECK(topography.missing == 0);
  CHECK(!topography.periodic);
  CHECK(metadata_value(topography, "instrument") == "Acme Profiler 3000");
  CHECK(metadata_value(topography, "date") == "2024-05-06T07:08:09+02:00");
  CHECK(metadata_value(topography, "creator") == "A. Tester");
  CHECK(metadata_value(topography, "comment") == "written by hand");
}

TEST_CASE("x3p: integer heights are scaled by CZ's Increment and Offset", "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.z_axis_extra = "<Increment>1e-9</Increment><Offset>5e-7</Offset>";
  SECTION("16-bit signed integers, with the invalid points of valid.bin") {
    x3p.data_type = "I";
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) append(x3p.data, static_cast<std::int16_t>(i + 10 * j - 7));
    // Points 1 (i = 1, j = 0) and 9 (i = 1, j = 2) invalid: bits LSB first, 12 bits in 2 bytes.
    x3p.valid = std::string{static_cast<char>(0xFD), static_cast<char>(0x0D)};
    const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
    CHECK(topography.missing == 2);
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        if (i == 1 && j != 1) {
          CHECK(std::isnan(topography.heights(i, j)));
        } else {
          CHECK(topography.heights(i, j) == Approx((i + 10 * j - 7) * 1e-9 + 5e-7));
        }
      }
    CHECK(topography.heights(0, 0) == Approx(4.93e-7));  // -7 nm below the offset: signed
  }
  SECTION("32-bit signed integers") {
    x3p.data_type = "L";
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i)
        append(x3p.data, static_cast<std::int32_t>(-100000 * (i + 10 * j)));
    const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
    CHECK(topography.missing == 0);
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i)
        CHECK(topography.heights(i, j) == Approx(-1e-4 * (i + 10 * j) + 5e-7));
  }
}

TEST_CASE("x3p: NaN in float data marks a missing point", "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.data_type = "F";
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      append(x3p.data, (i == 2 && j == 1) || (i == 3 && j == 2)
                           ? std::numeric_limits<float>::quiet_NaN()
                           : static_cast<float>(0.25 * (i + 10 * j)));
  SECTION("without an Increment of CZ, the values are metres") {
    const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
    CHECK(topography.missing == 2);
    CHECK(std::isnan(topography.heights(2, 1)));
    CHECK(std::isnan(topography.heights(3, 2)));
    CHECK(topography.heights(1, 2) == 0.25 * 21);
  }
  SECTION("with an Increment of CZ, it applies") {
    x3p.z_axis_extra = "<Increment>1e-6</Increment>";
    const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
    CHECK(topography.missing == 2);
    CHECK(topography.heights(1, 2) == Approx(0.25e-6 * 21));
  }
}

TEST_CASE("x3p: inline <Datum> values, an empty one missing", "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.size_x = "3";
  x3p.size_y = "2";
  x3p.data_list =
      "<Datum>1.5e-6</Datum><Datum>2e-6</Datum><Datum/>"
      "<Datum>-1e-6</Datum><Datum> 0 </Datum><Datum>4e-6</Datum>";
  const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
  REQUIRE(topography.heights.rows() == 3);
  REQUIRE(topography.heights.cols() == 2);
  CHECK(topography.missing == 1);
  CHECK(std::isnan(topography.heights(2, 0)));
  CHECK(topography.heights(1, 0) == 2e-6);
  CHECK(topography.heights(0, 1) == -1e-6);
  CHECK(topography.heights(2, 1) == 4e-6);
}

TEST_CASE("x3p: inline values with a prefix, comments and line ends between them",
          "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.size_x = "2";
  x3p.size_y = "2";
  const std::string first_values =
      "\n  <!-- row 0 <Datum>9</Datum> -->\n  <p:Datum>1e-6</p:Datum>\n  <Datum >\n2e-6\n</Datum>";
  x3p.data_list = first_values + "<?pi ignored?>";  // not a value: refused
  const fs::path spoiled = write_x3p(dir, x3p, "pi.x3p");
  CHECK_THROWS_WITH(read_x3p_topography(spoiled, size_limit(1 << 20)),
                    Catch::Contains("Record3/DataList holds \"<?pi ignored?>\""));
  x3p.data_list = first_values + "\n  <Datum/><Datum>4e-6</Datum>\n";
  const Topography topography = read_x3p_topography(write_x3p(dir, x3p), size_limit(1 << 20));
  CHECK(topography.heights(0, 0) == 1e-6);
  CHECK(topography.heights(1, 0) == 2e-6);
  CHECK(std::isnan(topography.heights(0, 1)));
  CHECK(topography.heights(1, 1) == 4e-6);
}

TEST_CASE("x3p: damaged or unsupported archives are refused by name", "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.data = reference_doubles();
  const auto refused = [&](const X3p& spoiled, const std::string& what) {
    const fs::path path = write_x3p(dir, spoiled);
    CHECK_THROWS_AS(read_x3p_topography(path, size_limit(1 << 20)), coatfft::InvalidArgument);
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::StartsWith(path.string() + ": ") && Catch::Contains(what));
  };
  SECTION("truncated point data") {
    X3p spoiled = x3p;
    spoiled.data.resize(spoiled.data.size() - 8);
    refused(spoiled, "88 bytes, but SizeX * SizeY = 4 * 3 values of 8 bytes take 96 (truncated)");
  }
  SECTION("sizes that do not match the data") {
    X3p spoiled = x3p;
    spoiled.size_y = "2";
    refused(spoiled, "96 bytes, but SizeX * SizeY = 4 * 2 values of 8 bytes take 64");
  }
  SECTION("a wrong MD5 of main.xml") {
    X3p spoiled = x3p;
    spoiled.record_checksum = md5_hex("something else");
    refused(spoiled, "main.xml does not match its MD5 checksum in md5checksum.hex");
  }
  SECTION("a checksum file that holds no MD5") {
    X3p spoiled = x3p;
    spoiled.record_checksum = "not-a-checksum";
    refused(spoiled, "not the MD5 checksum of main.xml");
  }
  SECTION("a wrong MD5 of the point data") {
    X3p spoiled = x3p;
    spoiled.data_checksum = md5_hex("other data");
    refused(spoiled, "bindata/data.bin does not match its MD5 checksum in main.xml");
  }
  SECTION("an unknown data type") {
    X3p spoiled = x3p;
    spoiled.data_type = "Q";
    refused(spoiled, "CZ/DataType = \"Q\" is not a data type of ISO 25178-72");
  }
  SECTION("a profile, not a surface") {
    X3p spoiled = x3p;
    spoiled.feature_type = "PRF";
    refused(spoiled, "FeatureType = \"PRF\", but only areal surfaces (SUR) are read");
  }
  SECTION("an absolute lateral axis") {
    X3p spoiled = x3p;
    spoiled.x_axis_type = "A";
    refused(spoiled, "CX/AxisType = \"A\", but only incremental lateral axes");
  }
  SECTION("several layers") {
    X3p spoiled = x3p;
    spoiled.size_z = "2";
    refused(spoiled, "SizeZ = 2, but only a single layer (SizeZ = 1) is read");
  }
  SECTION("a size that is not a number") {
    X3p spoiled = x3p;
    spoiled.size_x = "four";
    refused(spoiled, "SizeX = \"four\" is not a positive integer");
  }
  SECTION("a valid.bin too short for the points") {
    X3p spoiled = x3p;
    spoiled.valid = std::string(1, '\xFF');
    refused(spoiled, "bindata/valid.bin: 1 bytes, but 12 points need 2 (truncated)");
  }
  SECTION("inline data with too few values") {
    X3p spoiled = x3p;
    spoiled.data_list = "<Datum>1</Datum>";
    refused(spoiled, "Record3/DataList holds 1 values, but SizeX * SizeY = 12 (truncated)");
  }
  SECTION("inline data with more values than declared") {
    X3p spoiled = x3p;
    for (int k = 0; k < 13; ++k) spoiled.data_list += "<Datum>1</Datum>";
    refused(spoiled, "main.xml: Record3/DataList holds more than SizeX * SizeY = 12 values");
  }
  SECTION("inline data with another element or text") {
    X3p spoiled = x3p;
    spoiled.data_list = "<Datum>1</Datum><Value>2</Value>";
    refused(spoiled, "Record3/DataList holds \"<Value>\", where only <Datum> elements belong");
    spoiled.data_list = "<Datum>1</Datum> 2 ";
    refused(spoiled, "Record3/DataList holds the text \" 2 \", where only <Datum> elements");
  }
  SECTION("an inline value that is not a number") {
    X3p spoiled = x3p;
    for (int k = 0; k < 12; ++k)
      spoiled.data_list += k == 5 ? "<Datum>1 nm</Datum>" : "<Datum>1</Datum>";
    refused(spoiled, "main.xml: Record3/DataList/Datum = \"1 nm\" is not a number");
  }
  SECTION("a valid.bin longer than the points need") {
    X3p spoiled = x3p;
    spoiled.valid = std::string(3, '\xFF');
    refused(spoiled, "bindata/valid.bin: 3 bytes, but 12 points need 2");
  }
  SECTION("no main.xml") {
    X3p spoiled = x3p;
    spoiled.with_main = false;
    refused(spoiled, "not an X3P file: the archive holds no main.xml");
  }
}

TEST_CASE("x3p: files that are no X3P archive, or too large, are refused", "[topography][x3p]") {
  const TempDir dir;
  SECTION("not a zip archive") {
    const fs::path path = dir / "text.x3p";
    std::ofstream(path) << "this is not a zip archive\n";
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::StartsWith(path.string() + ": not an X3P file: not a zip archive"));
  }
  SECTION("an empty file") {
    const fs::path path = dir / "empty.x3p";
    std::ofstream{path};
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::StartsWith(path.string() + ": not an X3P file"));
  }
  SECTION("no md5checksum.hex") {
    X3p x3p;
    x3p.data = reference_doubles();
    const std::string xml = main_xml(x3p);
    const fs::path path = dir / "unchecked.x3p";
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", x3p.data}});
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::Contains("the archive holds no md5checksum.hex"));
  }
  SECTION("main.xml that is not XML") {
    const std::string xml = "<p:ISO5436_2><Record1>";
    const fs::path path = dir / "broken.x3p";
    write_zip(path, {{"main.xml", xml}, {"md5checksum.hex", md5_hex(xml)}});
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::Contains("main.xml is not well-formed XML"));
  }
  SECTION("more points than the limit allows") {
    X3p x3p;
    x3p.size_x = "100000";
    x3p.size_y = "100000";
    const fs::path path = write_x3p(dir, x3p);
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                      Catch::Contains("SizeX * SizeY = 100000 * 100000 points, more than the "
                                      "limit of 131072 points"));
  }
  SECTION("a file larger than the limit") {
    X3p x3p;
    x3p.data = reference_doubles();
    const fs::path path = write_x3p(dir, x3p);
    CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(100)),
                      Catch::Contains("more than the limit of 100 bytes"));
  }
  SECTION("a missing file") {
    CHECK_THROWS_AS(read_x3p_topography(dir / "absent.x3p", size_limit(1 << 20)),
                    coatfft::InvalidArgument);
  }
}

// Bombs: small archives that unpack to far more than they declare, or declare far more than
// they hold. Each is read in a child process whose memory may grow by little more than the map
// the file holds, within a CPU-time limit; each must end in a one-line refusal.
TEST_CASE("x3p: archives that unpack or declare more than they hold are refused early",
          "[topography][x3p]") {
  const TempDir dir;
  constexpr std::uintmax_t kHeadroom = std::uintmax_t{8} << 20;
  const auto refused = [&](const fs::path& path, const std::string& what,
                           const coatfft::topography::ReadOptions& options = {}) {
    const auto run = coatfft::testing::run_bounded(
        kHeadroom, 5, [&] { (void)read_x3p_topography(path, options); });
    CHECK(run.outcome.starts_with(path.string() + ": "));
    CHECK_THAT(run.outcome, Catch::Contains(what));
    CHECK(run.outcome.find('\n') == std::string::npos);
    CHECK(run.seconds < 5);
  };
  X3p x3p;
  x3p.with_data_checksum = false;
  SECTION("a data.bin far larger than SizeX * SizeY, refused before it is unpacked") {
    x3p.data = std::string(std::size_t{16} << 20, '\0');  // 16 MiB of zeros deflate to 16 kB
    refused(write_x3p(dir, x3p),
            "bindata/data.bin: 16777216 bytes, but SizeX * SizeY = 4 * 3 values of 8 bytes "
            "take 96");
  }
  SECTION("a zip header that declares fewer bytes than the entry unpacks to") {
    x3p.data = std::string(std::size_t{1} << 20, '\0');
    const fs::path path = write_x3p(dir, x3p);
    declare_size(path, "bindata/data.bin", 96);
    refused(path, "bindata/data.bin: unpacks to more than the 96 bytes the archive declares");
  }
  SECTION("a DataList padded beyond 256 bytes a value (and 1 MiB), refused as it is unpacked") {
    x3p.data_list = "<Datum>1</Datum>" + std::string(std::size_t{2} << 20, ' ');
    refused(write_x3p(dir, x3p),
            "main.xml: Record3/DataList takes more than 256 bytes a value of SizeX * SizeY = 12");
  }
  SECTION("a record of more than 1 MiB besides the DataList, refused as it is unpacked") {
    // Text without a tag after it: refused before main.xml ends, not held whole.
    const std::string xml = "<p:ISO5436_2><Record2><Comment>" + std::string(2 << 20, 'x');
    const fs::path path = dir / "comment.x3p";
    write_zip(path, {{"main.xml", xml}, {"md5checksum.hex", md5_hex(xml)}});
    refused(path, "main.xml: more than 1048576 bytes besides the values of Record3/DataList");
  }
  SECTION("SizeX * SizeY = 23000 * 23000 with three values inline") {
    x3p.size_x = x3p.size_y = "23000";
    x3p.data_list = "<Datum>1</Datum><Datum>2</Datum><Datum>3</Datum>";
    // The memory check passes: what the file holds must refuse it.
    const auto options = memory_limit(1e12);
    refused(write_x3p(dir, x3p),
            "main.xml: Record3/DataList holds 3 values, but SizeX * SizeY = 529000000 "
            "(truncated)",
            options);
  }
}

TEST_CASE("x3p: a map is held once, an inline one without a DOM node a value",
          "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  SECTION("bindata/data.bin: 2^20 doubles (8 MiB) stored, read within 12 MiB more memory") {
    x3p.size_x = x3p.size_y = "1024";
    x3p.stored = true;  // the archive holds the 8 MiB as they are: it is not read whole
    for (int k = 0; k < 1024 * 1024; ++k) append(x3p.data, k == 1000 ? 2.5e-6 : 0.0);
    const fs::path path = write_x3p(dir, x3p);
    const auto run = coatfft::testing::run_bounded(std::uintmax_t{12} << 20, 5, [&] {
      const Topography topography = read_x3p_topography(path, {});
      if (topography.heights(1000, 0) != 2.5e-6) throw std::runtime_error("a wrong value");
    });
    CHECK(run.outcome == "returned");
  }
  SECTION("Record3/DataList: 200000 values (3.4 MB of XML) read within 16 MiB more memory") {
    x3p.size_x = "500";
    x3p.size_y = "400";
    for (int k = 0; k < 200000; ++k) x3p.data_list += k == 7 ? "<Datum/>" : "<Datum>1e-6</Datum>";
    const fs::path path = write_x3p(dir, x3p);
    const auto run = coatfft::testing::run_bounded(std::uintmax_t{16} << 20, 5, [&] {
      const Topography topography = read_x3p_topography(path, {});
      if (topography.missing != 1 || !std::isnan(topography.heights(7, 0)) ||
          topography.heights(499, 399) != 1e-6)
        throw std::runtime_error("wrong values");
    });
    CHECK(run.outcome == "returned");
  }
}

TEST_CASE("x3p: a damaged data.bin is refused by its CRC-32 when main.xml has no MD5 of it",
          "[topography][x3p]") {
  const TempDir dir;
  X3p x3p;
  x3p.data = reference_doubles();
  x3p.with_data_checksum = false;
  x3p.stored = true;  // the bytes of data.bin lie in the file as they are
  const fs::path path = write_x3p(dir, x3p);
  CHECK(read_x3p_topography(path, size_limit(1 << 20)).heights(3, 2) == reference_height(3, 2));
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto at = bytes.find(x3p.data);
  REQUIRE(at != std::string::npos);
  bytes[at + 13] = static_cast<char>(bytes[at + 13] ^ 0x40);  // one bit of the second value
  std::ofstream(path, std::ios::binary) << bytes;
  CHECK_THROWS_WITH(read_x3p_topography(path, size_limit(1 << 20)),
                    Catch::StartsWith(path.string() + ": bindata/data.bin: cannot be unpacked") &&
                        Catch::Contains("CRC"));
}
