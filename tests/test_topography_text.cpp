// Text topographies (matrices and x y z rows), the conversion to metres, and the filling of
// missing points, through read_topography (topography/topography.hpp), on files written here.
#include <Eigen/LU>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "topography/topography.hpp"

namespace fs = std::filesystem;
using namespace coatfft;
using topography::read_topography;

namespace {
fs::path text_file(const std::string& name, const std::string& content) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_topography_text_tests";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir / name;
}

// "x y z" rows of z = 1 + i + 10 j on an nx x ny grid of spacing dx, dy, in a shuffled order.
std::string xyz_rows(int nx, int ny, double dx, double dy, unsigned seed) {
  std::vector<std::string> rows;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      rows.push_back(std::to_string(0.5 + i * dx) + " " + std::to_string(-2 + j * dy) + " " +
                     std::to_string(1 + i + 10 * j) + "\n");
  std::shuffle(rows.begin(), rows.end(), std::mt19937(seed));
  std::string text = "x y z\n";
  for (const auto& r : rows) text += r;
  return text;
}
// Reading in `unit` (a file without a unit of its own), the other options their defaults.
topography::ReadOptions in_unit(const std::string& unit) {
  topography::ReadOptions options;
  options.unit = unit;
  return options;
}

}  // namespace

TEST_CASE("text: a matrix with a header, in the unit asked for; x along columns",
          "[topography][text]") {
  const auto path = text_file("m.csv", "\xEF\xBB\xBFheight map\n1\t2\t3\n4\t5\t6\n");
  const auto t = read_topography(path, in_unit("um"));
  CHECK(t.format == "csv");
  REQUIRE(t.heights.rows() == 3);  // nx: the columns
  REQUIRE(t.heights.cols() == 2);
  CHECK(t.heights(2, 0) == Approx(3e-6));
  CHECK(t.heights(0, 1) == Approx(4e-6));
  CHECK_FALSE(t.lx);
  CHECK(t.unit == "um");
  // Metres when no unit is asked for.
  CHECK(read_topography(path).heights(2, 1) == 6.0);
}

TEST_CASE("text: x y z rows in any order on a regular grid", "[topography][text][xyz]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const int nx = 4 + static_cast<int>(seed), ny = 3;
    const auto t =
        read_topography(text_file("r.xyz", xyz_rows(nx, ny, 0.25, 0.5, seed)), in_unit("mm"));
    CHECK(t.format == "xyz");
    REQUIRE(t.heights.rows() == nx);
    REQUIRE(t.heights.cols() == ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) CHECK(t.heights(i, j) == Approx(1e-3 * (1 + i + 10 * j)));
    // Size = points x spacing, in the unit: nx 0.25 mm by 3 x 0.5 mm.
    CHECK(*t.lx == Approx(nx * 0.25e-3));
    CHECK(*t.ly == Approx(1.5e-3));
  }
}

TEST_CASE("text: x y z rows off a regular grid are refused naming the axis",
          "[topography][text][xyz]") {
  CHECK_THROWS_WITH(
      read_topography(text_file("n.xyz", "0 0 1\n1 0 2\n3 0 3\n0 1 4\n1 1 5\n3 1 6\n")),
      Catch::Contains("the x coordinates are not uniformly spaced"));
  CHECK_THROWS_WITH(read_topography(text_file("d.xyz", "0 0 1\n1 0 2\n0 1 3\n0 1 4\n")),
                    Catch::Contains("is given twice"));
}

TEST_CASE("missing points: refused with their count, or filled by the harmonic rule",
          "[topography][missing]") {
  // A plane is discrete-harmonic at every inner point: holes inside it are filled exactly.
  std::string text;
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 7; ++i) {
      const bool hole = (i == 2 && j >= 1 && j <= 3) || (i == 3 && j == 2) || (i == 5 && j == 4);
      text += hole ? "nan" : std::to_string(0.5 + 0.25 * i - 0.125 * j);
      text += i < 6 ? "," : "\n";
    }
  }
  const auto path = text_file("holes.csv", text);
  CHECK_THROWS_WITH(read_topography(path), Catch::Contains("5 of 42 points are missing"));
  topography::ReadOptions fill;
  fill.missing = topography::MissingPoints::fill;
  const auto t = read_topography(path, fill);
  CHECK(t.missing == 5);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 7; ++i) CHECK(t.heights(i, j) == Approx(0.5 + 0.25 * i - 0.125 * j));
  CHECK_THROWS_WITH(read_topography(text_file("inf.csv", "1,2\n3,inf\n")),
                    Catch::Contains("row 1, column 1: an infinite height"));
  CHECK_THROWS_WITH(read_topography(text_file("all.csv", "nan,nan\nnan,nan\n"), fill),
                    Catch::Contains("every point is missing"));
}

TEST_CASE("missing points at the edge: each filled point is the mean of its neighbours",
          "[topography][missing]") {
  // The defining property of the rule, with holes on the edges and corners too.
  Field z = Field::Random(9, 8);
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{8, 3}, std::pair{4, 4}, std::pair{4, 5},
                             std::pair{5, 4}, std::pair{0, 7}, std::pair{1, 7}})
    z(i, j) = std::nan("");
  const Field before = z;
  CHECK(topography::fill_missing_points(z) == 7);
  for (Eigen::Index j = 0; j < 8; ++j)
    for (Eigen::Index i = 0; i < 9; ++i) {
      if (!std::isnan(before(i, j))) {
        CHECK(z(i, j) == before(i, j));
        continue;
      }
      double sum = 0, n = 0;
      for (const auto& [a, b] :
           {std::pair{i + 1, j}, std::pair{i - 1, j}, std::pair{i, j + 1}, std::pair{i, j - 1}})
        if (a >= 0 && a < 9 && b >= 0 && b < 8) sum += z(a, b), n += 1;
      CHECK(z(i, j) == Approx(sum / n).margin(1e-14));
    }
}

TEST_CASE("read_topography: unknown formats and units are refused", "[topography]") {
  CHECK_THROWS_WITH(read_topography(text_file("z.bmp", "x")),
                    Catch::Contains("unknown topography format \".bmp\""));
  CHECK_THROWS_WITH(read_topography(text_file("u.csv", "1,2\n3,4\n"), in_unit("furlong")),
                    Catch::Contains("unknown unit \"furlong\""));
  CHECK_THROWS_WITH(read_topography(text_file("p.csv", "1,2,3\n")),
                    Catch::Contains("at least 2 x 2"));
}

namespace {
// The harmonic rule solved independently: every missing point's equation in one dense system
// (LU with full pivoting), the known heights on the right.
Field dense_fill(const Field& z) {
  std::vector<Eigen::Index> index(static_cast<std::size_t>(z.size()), -1);
  Eigen::Index n = 0;
  for (Eigen::Index k = 0; k < z.size(); ++k)
    if (std::isnan(z.data()[k])) index[static_cast<std::size_t>(k)] = n++;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < z.cols(); ++j)
    for (Eigen::Index i = 0; i < z.rows(); ++i) {
      const Eigen::Index row = index[static_cast<std::size_t>(i + z.rows() * j)];
      if (row < 0) continue;
      for (const auto& [p, q] :
           {std::pair{i + 1, j}, std::pair{i - 1, j}, std::pair{i, j + 1}, std::pair{i, j - 1}}) {
        if (p < 0 || p >= z.rows() || q < 0 || q >= z.cols()) continue;
        a(row, row) += 1;
        const Eigen::Index col = index[static_cast<std::size_t>(p + z.rows() * q)];
        if (col >= 0)
          a(row, col) -= 1;
        else
          b(row) += z(p, q);
      }
    }
  const Eigen::VectorXd x = a.fullPivLu().solve(b);
  Field out = z;
  for (Eigen::Index k = 0; k < z.size(); ++k)
    if (index[static_cast<std::size_t>(k)] >= 0)
      out.data()[k] = x(index[static_cast<std::size_t>(k)]);
  return out;
}
}  // namespace

TEST_CASE("missing points: the fill equals a dense solve of the harmonic rule, at any scale",
          "[topography][missing]") {
  // A wide hole (an 8 x 6 block touching the edge), a line and scattered points on 20 x 16.
  Field z = Field::Random(20, 16);
  for (Eigen::Index j = 0; j < 16; ++j)
    for (Eigen::Index i = 0; i < 20; ++i)
      if ((i >= 12 && j >= 3 && j < 9) || j == 12 || (i * 7 + j * 3) % 11 == 0)
        z(i, j) = std::nan("");
  const Field reference = dense_fill(z);
  Field filled = z;
  CHECK(topography::fill_missing_points(filled) == static_cast<std::size_t>(z.isNaN().count()));
  // LU's rounding on a system of condition number about 1e3.
  CHECK((filled - reference).abs().maxCoeff() < 1e-12);
  // Heights near the largest double: the same fill scaled (the sums of four neighbours would
  // overflow unscaled). 2^1023 scales exactly.
  const double big = std::ldexp(1.0, 1023);
  Field huge = z * big;
  topography::fill_missing_points(huge);
  REQUIRE(huge.allFinite());
  CHECK((huge / big - reference).abs().maxCoeff() < 1e-12);
}

TEST_CASE(
    "missing points: a fill beyond the memory limit is refused before it is made, naming "
    "the count",
    "[topography][missing]") {
  // One known point on 160^2: 25599 unknowns, 13.1 MB before the factor (512 bytes each), whose
  // minimum degree factor adds some 10^5 nonzeros of 12 bytes, beyond the 0.9 MB left of 14 MB.
  Field z = Field::Constant(160, 160, std::nan(""));
  z(3, 5) = 1e-6;
  Field copy = z;
  CHECK_THROWS_WITH(topography::fill_missing_points(copy, 8e6, "h.npy"),
                    Catch::Contains("h.npy: filling the missing points needs about") &&
                        Catch::Contains("25599 missing points,") &&
                        Catch::Contains("is the limit (--max-memory)"));
  CHECK(copy.isNaN().count() == 25599);  // untouched
  // A hole of 1200^2 points: refused at once on the estimate from its size (16 x 1200^3 = 2.8e10
  // multiply-adds), whatever the memory.
  Field wide = Field::Constant(1200, 1200, std::nan(""));
  wide(0, 0) = 0.0;
  CHECK_THROWS_WITH(topography::fill_missing_points(wide, 1e12, "w.npy"),
                    Catch::Contains("w.npy: filling 1439999 missing points takes about") &&
                        Catch::Contains("estimated from the holes' sizes"));
  // Past the first estimate, refused on the factor's count.
  CHECK_THROWS_WITH(topography::fill_missing_points(copy, 14e6, "h.npy"),
                    Catch::Contains("25599 missing points (a factor of more than"));
}
