// NetCDF topographies: files laid out by netcdf-c's own calls here, in SurfaceTopography's
// (x, y) order and in xarray's (y, x), read by read_topography; coatfft's writer read back; bad
// files refused. (python/tests/test_topography.py reads files that netCDF4-python writes.)
#include <netcdf.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "topography/netcdf_writer.hpp"
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
  topography::write_heights(path, topography::HeightsFormat::netcdf, z, grid, false,
                            {{{"source", "test"}}, {}});
  const auto t = read_topography(path);
  CHECK((t.heights - z).abs().maxCoeff() == 0.0);
  CHECK(*t.lx == 3e-6);
  CHECK(*t.ly == 5e-6);
  CHECK_FALSE(*t.periodic);
  CHECK(t.unit == "m");
  // An existing file is never overwritten.
  CHECK_THROWS_WITH(
      topography::write_heights(path, topography::HeightsFormat::netcdf, z, grid, false),
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
    topography::NetcdfDataset d{Grid(s.n, s.n, 1.0, 1.0), false, {}, {}, {}};
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
    CHECK(topography::needs_64bit_data(d) == (status == NC_EVARSIZE));
    refused += status == NC_EVARSIZE;
  }
  CHECK(refused == 5);  // 23171^2 and 32768^2 with 2 or 3 maps, 5462^2 after the stack
}
