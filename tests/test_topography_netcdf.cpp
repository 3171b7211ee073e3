// NetCDF topographies: files laid out by netcdf-c's own calls here, in SurfaceTopography's
// (x, y) order and in xarray's (y, x), read by read_topography; coatfft's writer read back; bad
// files refused. (python/tests/test_topography.py reads files that netCDF4-python writes.)
#include <netcdf.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/netcdf_writer.hpp"
#include "tests/bounded_call.hpp"
#include "topography/topography.hpp"

namespace fs = std::filesystem;
using namespace coatfft;
using topography::read_topography;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_topography_netcdf_tests";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

void ok(int status) {
  REQUIRE(status == NC_NOERR);
}

// heights(x, y) = 1 + i + 10 j (or over (y, x) with `y_first`), x and y with length 2 nx and
// 3 ny, periodic, in `unit`; one point is the fill value.
fs::path write_file(const std::string& name, int nx, int ny, bool y_first, const char* unit) {
  const fs::path path = scratch(name);
  int id = 0, dx = 0, dy = 0, vx = 0, vy = 0, vh = 0;
  ok(nc_create(path.c_str(), NC_NETCDF4, &id));
  ok(nc_def_dim(id, "x", static_cast<size_t>(nx), &dx));
  ok(nc_def_dim(id, "y", static_cast<size_t>(ny), &dy));
  ok(nc_def_var(id, "x", NC_DOUBLE, 1, &dx, &vx));
  ok(nc_def_var(id, "y", NC_DOUBLE, 1, &dy, &vy));
  const int dims[2] = {y_first ? dy : dx, y_first ? dx : dy};
  ok(nc_def_var(id, "heights", NC_FLOAT, 2, dims, &vh));
  const double lx = 2.0 * nx, ly = 3.0 * ny, fill = -999;
  const long long periodic = 1;
  ok(nc_put_att_double(id, vx, "length", NC_DOUBLE, 1, &lx));
  ok(nc_put_att_double(id, vy, "length", NC_DOUBLE, 1, &ly));
  ok(nc_put_att_longlong(id, vx, "periodic", NC_INT64, 1, &periodic));
  ok(nc_put_att_longlong(id, vy, "periodic", NC_INT64, 1, &periodic));
  ok(nc_put_att_text(id, vx, "length_unit", std::string(unit).size(), unit));
  ok(nc_put_att_text(id, vy, "length_unit", std::string(unit).size(), unit));
  ok(nc_put_att_double(id, vh, "_FillValue", NC_FLOAT, 1, &fill));
  ok(nc_put_att_text(id, NC_GLOBAL, "instrument", 4, "test"));
  std::vector<float> values;
  for (int a = 0; a < (y_first ? ny : nx); ++a)
    for (int b = 0; b < (y_first ? nx : ny); ++b) {
      const int i = y_first ? b : a, j = y_first ? a : b;
      values.push_back(i == 1 && j == 0 ? -999.f : static_cast<float>(1 + i + 10 * j));
    }
  ok(nc_put_var_float(id, vh, values.data()));
  ok(nc_close(id));
  return path;
}
}  // namespace

TEST_CASE("netcdf: SurfaceTopography's (x, y) and xarray's (y, x) layouts, units, fill values",
          "[topography][netcdf]") {
  topography::ReadOptions fill;
  fill.missing = topography::MissingPoints::fill;
  for (const bool y_first : {false, true}) {
    const auto path = write_file(y_first ? "yx.nc" : "xy.nc", 5, 3, y_first, "\u00b5m");
    CHECK_THROWS_WITH(read_topography(path), Catch::Contains("1 of 15 points are missing"));
    const auto t = read_topography(path, fill);
    CHECK(t.format == "netcdf");
    REQUIRE(t.heights.rows() == 5);
    REQUIRE(t.heights.cols() == 3);
    CHECK(t.heights(4, 2) == Approx(25e-6));  // 1 + 4 + 20, in um
    CHECK(t.heights(0, 1) == Approx(11e-6));
    CHECK(*t.lx == Approx(10e-6));
    CHECK(*t.ly == Approx(9e-6));
    CHECK(*t.periodic);
    CHECK(t.unit == "\u00b5m");
    CHECK(t.missing == 1);
    CHECK(t.metadata.at(0) == std::pair<std::string, std::string>{"instrument", "test"});
    // The file's unit wins; a different one asked for is refused.
    topography::ReadOptions in_nm = fill;
    in_nm.unit = "nm";
    CHECK_THROWS_WITH(read_topography(path, in_nm),
                      Catch::Contains("the file's unit is \"\u00b5m\""));
  }
}

TEST_CASE("netcdf: coatfft's heights file read back as written", "[topography][netcdf]") {
  const Grid grid(6, 4, 3e-6, 5e-6);
  Field z(6, 4);
  for (Eigen::Index j = 0; j < 4; ++j)
    for (Eigen::Index i = 0; i < 6; ++i) z(i, j) = 1e-9 * static_cast<double>(i + 10 * j);
  const auto path = scratch("w.nc");
  io::write_heights(path, io::HeightsFormat::netcdf, z, grid, false, {{{"source", "test"}}, {}});
  const auto t = read_topography(path);
  CHECK((t.heights - z).abs().maxCoeff() == 0.0);
  CHECK(*t.lx == 3e-6);
  CHECK(*t.ly == 5e-6);
  CHECK_FALSE(*t.periodic);
  CHECK(t.unit == "m");
  // An existing file is never overwritten.
  CHECK_THROWS_WITH(io::write_heights(path, io::HeightsFormat::netcdf, z, grid, false),
                    Catch::Contains("cannot create"));
}

TEST_CASE("netcdf: truncated files, no heights, wrong dimensions are refused",
          "[topography][netcdf]") {
  const auto good = write_file("g.nc", 4, 4, false, "m");
  std::string bytes(fs::file_size(good), '\0');
  std::ifstream(good, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const auto cut = scratch("cut.nc");
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  CHECK_THROWS_WITH(read_topography(cut), Catch::Contains("cut.nc"));
  const auto none = scratch("none.nc");
  int id = 0, d = 0, v = 0;
  ok(nc_create(none.c_str(), NC_CLOBBER, &id));
  ok(nc_def_dim(id, "x", 3, &d));
  ok(nc_def_var(id, "z", NC_DOUBLE, 1, &d, &v));
  ok(nc_close(id));
  CHECK_THROWS_WITH(read_topography(none), Catch::Contains("no variable named heights"));
  const auto flat = scratch("flat.nc");
  ok(nc_create(flat.c_str(), NC_CLOBBER, &id));
  ok(nc_def_dim(id, "x", 3, &d));
  ok(nc_def_var(id, "heights", NC_DOUBLE, 1, &d, &v));
  ok(nc_close(id));
  CHECK_THROWS_WITH(read_topography(flat), Catch::Contains("has 1 dimensions, not 2"));
}

TEST_CASE("netcdf: variables beyond the 64-bit offset format's limit take the 64-bit data format",
          "[topography][netcdf]") {
  // The reference is netcdf-c's own check of the format: the same variables defined in a 64-bit
  // offset file, ended without data, are refused (NC_EVARSIZE) exactly when needs_64bit_data
  // says so. Maps of 16384^2 (2 GiB), 23170^2 (just below 2^32 bytes), 23171^2 (just above) and
  // 32768^2 cells, one to three of them (the last variable may be of any size), and stacks of
  // 6 x 3 stress planes over 5461^2 and 5462^2 cells (below and above) before a map.
  struct Shape {
    std::ptrdiff_t n;
    int maps;
    bool stack;
  };
  std::vector<Shape> shapes;
  for (const std::ptrdiff_t n : {16384, 23170, 23171, 32768})
    for (const int maps : {1, 2, 3}) shapes.push_back({n, maps, false});
  for (const std::ptrdiff_t n : {5461, 5462}) shapes.push_back({n, 1, true});
  int refused = 0;
  for (const Shape& s : shapes) {
    io::NetcdfDataset d{Grid(s.n, s.n, 1.0, 1.0), false, {}, {}, {}};
    if (s.stack) {
      d.dimensions = {{"depth", 3, {}, {}}, {"component", 6, {}, {}}};
      d.variables.push_back({"stress", {"depth", "component"}, {}, {}});
    }
    for (int k = 0; k < s.maps; ++k) d.variables.push_back({"map" + std::to_string(k), {}, {}, {}});
    const fs::path path = scratch("limit.nc");
    int nc = -1;
    ok(nc_create(path.c_str(), NC_64BIT_OFFSET, &nc));
    int fill = 0;
    ok(nc_set_fill(nc, NC_NOFILL, &fill));
    int x = -1, y = -1, depth = -1, component = -1, var = -1;
    ok(nc_def_dim(nc, "x", static_cast<std::size_t>(s.n), &x));
    ok(nc_def_dim(nc, "y", static_cast<std::size_t>(s.n), &y));
    ok(nc_def_dim(nc, "depth", 3, &depth));
    ok(nc_def_dim(nc, "component", 6, &component));
    ok(nc_def_var(nc, "x", NC_DOUBLE, 1, &x, &var));
    ok(nc_def_var(nc, "y", NC_DOUBLE, 1, &y, &var));
    for (const auto& v : d.variables) {
      std::vector<int> dims =
          v.leading.empty() ? std::vector<int>{} : std::vector{depth, component};
      dims.insert(dims.end(), {x, y});
      ok(nc_def_var(nc, v.name.c_str(), NC_DOUBLE, static_cast<int>(dims.size()), dims.data(),
                    &var));
    }
    const int status = nc_enddef(nc);
    nc_close(nc);
    fs::remove(path);
    INFO(s.n << "^2 cells, " << s.maps << " maps" << (s.stack ? " after a stack" : ""));
    REQUIRE((status == NC_NOERR || status == NC_EVARSIZE));
    CHECK(io::needs_64bit_data(d) == (status == NC_EVARSIZE));
    refused += status == NC_EVARSIZE;
  }
  CHECK(refused == 5);  // 23171^2 and 32768^2 with 2 or 3 maps, 5462^2 after the stack
}

namespace {
// Creates `path` in `format` with dimensions x and y of nx and ny points and the variable
// heights(x, y) of `type`, left in define mode: the file's id and the variable's.
std::pair<int, int> create_heights(const fs::path& path, int format, nc_type type, std::size_t nx,
                                   std::size_t ny) {
  int id = 0, dims[2] = {}, var = 0;
  ok(nc_create(path.c_str(), format, &id));
  ok(nc_def_dim(id, "x", nx, &dims[0]));
  ok(nc_def_dim(id, "y", ny, &dims[1]));
  ok(nc_def_var(id, "heights", type, 2, dims, &var));
  return {id, var};
}

// A 23000 x 23000 map of doubles (4.2 GB) declared in `format` and never written.
fs::path declared_map(const std::string& name, int format, bool deflate) {
  const fs::path path = scratch(name);
  const auto [id, var] = create_heights(path, format, NC_DOUBLE, 23000, 23000);
  int fill = 0;
  ok(nc_set_fill(id, NC_NOFILL, &fill));
  if (deflate) ok(nc_def_var_deflate(id, var, 1, 1, 1));
  ok(nc_close(id));
  return path;
}

// The peak resident memory of a child that does nothing [MiB]: what a child starts with.
double child_start_mib() {
  return coatfft_test::run_bounded([] {}, 1u << 30, 30).peak_rss_mib;
}

// The message read_topography(path) refuses with, in a child of at most 512 MiB more address
// space and 30 s, which must end in 5 s having taken less than 100 MiB more than it started with.
std::string bounded_refusal(const fs::path& path) {
  const double start_mib = child_start_mib();
  const auto call = coatfft_test::run_bounded([&] { read_topography(path); }, 512u << 20, 30);
  INFO(path << ": " << call.error << "; " << call.seconds << " s, " << call.peak_rss_mib << " MiB, "
            << start_mib << " MiB at start");
  CHECK(call.returned);
  CHECK(call.seconds < 5);
  CHECK(call.peak_rss_mib - start_mib < 100);
  CHECK(call.error.find('\n') == std::string::npos);
  return call.error;
}
}  // namespace

TEST_CASE("netcdf: heights declared beyond what the file holds are refused before allocation",
          "[topography][netcdf]") {
  // A NetCDF-3 header cut to 4 KiB: its 4.2 GB of heights are not in the file.
  const auto cut = declared_map("cut3.nc", NC_64BIT_DATA, false);
  fs::resize_file(cut, 4096);
  CHECK_THAT(bounded_refusal(cut),
             Catch::StartsWith(cut.string() +
                               ": heights: x * y = 23000 * 23000 points of 8 bytes "
                               "take 4232000000 bytes, more than the file's 4096: the file is "
                               "cut short, or its heights were never written"));
  // NetCDF-4 files of a few KiB whose heights were never written: HDF5 would return 4.2 GB of
  // fill. Deflated, they would take at least 1/1032 of their size.
  const auto unwritten = declared_map("unwritten4.nc", NC_NETCDF4, false);
  CHECK_THAT(bounded_refusal(unwritten),
             Catch::StartsWith(unwritten.string() + ": heights: x * y = 23000 * 23000 points") &&
                 Catch::Contains("the file is cut short, or its heights were never written"));
  const auto deflated = declared_map("deflated4.nc", NC_NETCDF4, true);
  CHECK_THAT(bounded_refusal(deflated),
             Catch::Contains("compressed, take at least 4100776 bytes (deflate compresses at most "
                             "1032:1)") &&
                 Catch::Contains("never written, or compressed beyond deflate"));
}

TEST_CASE("netcdf: a constant map deflated as far as deflate goes is read",
          "[topography][netcdf]") {
  // 512 x 512 equal doubles (2 MiB) deflate to a few KiB: within the 1032:1 bound, and read.
  const fs::path path = scratch("constant.nc");
  const auto [id, var] = create_heights(path, NC_NETCDF4, NC_DOUBLE, 512, 512);
  ok(nc_def_var_deflate(id, var, 1, 1, 9));
  const std::vector<double> values(512 * 512, 2.5e-6);
  ok(nc_put_var_double(id, var, values.data()));
  ok(nc_close(id));
  CHECK(fs::file_size(path) < 512 * 512 * 8 / 100);
  const auto t = read_topography(path);
  CHECK(t.heights.minCoeff() == 2.5e-6);
  CHECK(t.heights.maxCoeff() == 2.5e-6);
}

namespace {
// heights(x, y) of 4 x 3 points of `type` in `format`, of which x = 0 and 1 are written
// (1 + i + 10 j) and x = 2 and 3 are left to netcdf-c's fill; `define` adds to the variable.
fs::path half_written(const std::string& name, int format, nc_type type,
                      const std::function<void(int, int)>& define = {}) {
  const fs::path path = scratch(name);
  const auto [id, var] = create_heights(path, format, type, 4, 3);
  if (define) define(id, var);
  ok(nc_enddef(id));
  const std::vector<double> values{1, 11, 21, 2, 12, 22};
  const std::size_t start[2] = {0, 0}, count[2] = {2, 3};
  ok(nc_put_vara_double(id, var, start, count, values.data()));
  ok(nc_close(id));
  return path;
}
}  // namespace

TEST_CASE("netcdf: heights a writer never reached hold the default fill: missing",
          "[topography][netcdf]") {
  const topography::ReadOptions fill{"", topography::MissingPoints::fill};
  for (const int format : {NC_CLOBBER, NC_64BIT_DATA, NC_NETCDF4})
    for (const nc_type type : {NC_FLOAT, NC_DOUBLE, NC_INT}) {
      INFO("format " << format << ", type " << type);
      const auto path = half_written("half.nc", format, type);
      CHECK_THROWS_WITH(read_topography(path),
                        Catch::StartsWith(path.string() + ": 6 of 12 points are missing"));
      const auto t = read_topography(path, fill);
      CHECK(t.missing == 6);
      CHECK(t.heights(1, 2) == 22);
      // Filled by the harmonic rule (the mean of the neighbours), so below the largest height.
      CHECK(t.heights.maxCoeff() == 22);
    }
  // A variable written without filling, or with a _FillValue of its own, has no default fill:
  // the same value is then a height like any other (here an unwritten point filled explicitly).
  const auto own_fill = half_written("own.nc", NC_NETCDF4, NC_DOUBLE, [](int id, int var) {
    const double minus = -999;
    ok(nc_put_att_double(id, var, "_FillValue", NC_DOUBLE, 1, &minus));
  });
  CHECK_THROWS_WITH(read_topography(own_fill), Catch::Contains("6 of 12 points are missing"));
  const auto no_fill = half_written("nofill.nc", NC_NETCDF4, NC_DOUBLE, [](int id, int var) {
    ok(nc_def_var_fill(id, var, 1, nullptr));
  });
  int id = 0, var = 0;
  ok(nc_open(no_fill.c_str(), NC_WRITE, &id));
  ok(nc_inq_varid(id, "heights", &var));
  const std::vector<double> rest(6, NC_FILL_DOUBLE);
  const std::size_t start[2] = {2, 0}, count[2] = {2, 3};
  ok(nc_put_vara_double(id, var, start, count, rest.data()));
  ok(nc_close(id));
  const auto t = read_topography(no_fill);
  CHECK(t.missing == 0);
  CHECK(t.heights(3, 2) == NC_FILL_DOUBLE);
}

TEST_CASE("netcdf: attributes of the wrong type and text heights are refused, named",
          "[topography][netcdf]") {
  struct Case {
    const char* what;
    std::function<void(int, int)> define;
    const char* message;
  };
  const auto text = [](const char* name, const char* value) {
    return [=](int id, int var) { ok(nc_put_att_text(id, var, name, std::strlen(value), value)); };
  };
  const std::vector<Case> cases{
      {"scale_factor = \"abc\"", text("scale_factor", "abc"),
       ": the attribute scale_factor of heights is the text \"abc\", not a number"},
      {"missing_value = \"none\"", text("missing_value", "none"),
       ": the attribute missing_value of heights is the text \"none\", not a number"},
      {"units = 3",
       [](int id, int var) {
         const int three = 3;
         ok(nc_put_att_int(id, var, "units", NC_INT, 1, &three));
       },
       ": the attribute units of heights is of type int, not text"},
      {"add_offset = {1, 2}",
       [](int id, int var) {
         const double two[2] = {1, 2};
         ok(nc_put_att_double(id, var, "add_offset", NC_DOUBLE, 2, two));
       },
       ": the attribute add_offset of heights holds 2 numbers, not one"},
      {"x: periodic = \"yes\"",
       [](int id, int) {
         int dim = 0, x = 0;
         ok(nc_inq_dimid(id, "x", &dim));
         ok(nc_def_var(id, "x", NC_DOUBLE, 1, &dim, &x));
         ok(nc_put_att_text(id, x, "periodic", 3, "yes"));
       },
       ": the attribute periodic of x is the text \"yes\", not a number"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const auto path = half_written("attribute.nc", NC_NETCDF4, NC_DOUBLE, c.define);
    CHECK_THROWS_WITH(read_topography(path), Catch::Equals(path.string() + c.message));
  }
  // Global attributes are metadata: numbers and lists of strings there are skipped, not refused.
  const auto global = half_written("global.nc", NC_NETCDF4, NC_DOUBLE, [](int id, int) {
    const int year = 2026;
    const char* names[2] = {"a", "b"};
    ok(nc_put_att_int(id, NC_GLOBAL, "year", NC_INT, 1, &year));
    ok(nc_put_att_string(id, NC_GLOBAL, "operators", 2, names));
    ok(nc_put_att_text(id, NC_GLOBAL, "instrument", 4, "test"));
  });
  const topography::ReadOptions fill{"", topography::MissingPoints::fill};
  CHECK(read_topography(global, fill).metadata ==
        std::vector<std::pair<std::string, std::string>>{{"instrument", "test"}});
  for (const nc_type type : {NC_CHAR, NC_STRING}) {
    const fs::path path = scratch("text.nc");
    ok(nc_close(create_heights(path, NC_NETCDF4, type, 2, 2).first));
    CHECK_THROWS_WITH(read_topography(path),
                      Catch::Equals(path.string() + ": the variable heights holds text (of type " +
                                    (type == NC_CHAR ? "char" : "string") + "), not numbers"));
  }
}

TEST_CASE("netcdf: a map is held once while it is read", "[topography][netcdf]") {
  // 4096 x 1024 floats laid out (x, y): the file in memory (16 MiB), the map (32 MiB) and a
  // block of the transposed read (2 MiB) make 50 MiB; a second copy of the map would make 82.
  const fs::path path = scratch("large.nc");
  const auto [id, var] = create_heights(path, NC_64BIT_DATA, NC_FLOAT, 4096, 1024);
  ok(nc_enddef(id));
  std::vector<float> values(std::size_t{4096} * 1024);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<float>(k % 1000);
  ok(nc_put_var_float(id, var, values.data()));
  ok(nc_close(id));
  const double start_mib = child_start_mib();
  const auto call = coatfft_test::run_bounded([&] { read_topography(path); }, 1u << 30, 30);
  INFO(call.error << "; peak " << call.peak_rss_mib << " MiB, " << start_mib << " MiB at start");
  CHECK(call.returned);
  CHECK(call.error.empty());
  // AddressSanitizer's shadow and quarantine add to the peak: the Release build checks it.
  if (!coatfft_test::address_sanitized()) CHECK(call.peak_rss_mib - start_mib < 66);
}

TEST_CASE("netcdf: a NetCDF-3 header declaring more than its bytes hold is refused",
          "[topography][netcdf]") {
  // netcdf-c allocates an array for the variables a header counts before reading them: 3.8e9 of
  // them in 120 bytes would ask for 30 GB. The count of a small file's variables, then of the
  // characters of its first dimension's name, made huge.
  const auto good = half_written("counts.nc", NC_CLOBBER, NC_DOUBLE);
  std::string bytes(fs::file_size(good), '\0');
  std::ifstream(good, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  for (const std::string& count :
       {std::string("\0\0\0\x0b\0\0\0\x01", 8), std::string("\0\0\0\x02\0\0\0\x01x", 9)}) {
    std::string damaged = bytes;
    const auto at = damaged.find(count);
    REQUIRE(at != std::string::npos);
    damaged[at + 4] = '\xe5';
    const auto path = scratch("counts_damaged.nc");
    std::ofstream(path, std::ios::binary) << damaged;
    CHECK_THAT(bounded_refusal(path),
               Catch::StartsWith(path.string() + ": the NetCDF header declares 384") &&
                   Catch::EndsWith("bytes left: the file is damaged"));
  }
  // The type of heights (NC_DOUBLE, after its attribute list: ABSENT) made 12, which NetCDF-3
  // does not have: netcdf-c 4.9.0 divides by its size, 0 (SIGFPE).
  std::string damaged = bytes;
  const auto at = damaged.find(std::string("\0\0\0\0\0\0\0\0\0\0\0\x06", 12));
  REQUIRE(at != std::string::npos);
  damaged[at + 11] = '\x0c';
  const auto path = scratch("type_damaged.nc");
  std::ofstream(path, std::ios::binary) << damaged;
  CHECK_THROWS_WITH(read_topography(path),
                    path.string() +
                        ": the NetCDF header gives a variable the type 12, not one of "
                        "NetCDF-3's: the file is damaged");
}
