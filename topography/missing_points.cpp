#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "topography/topography.hpp"

namespace coatfft::topography {

namespace {
using Index = Eigen::Index;
using Matrix = Eigen::SparseMatrix<double>;
using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

// Memory the fill takes besides the factor [bytes per unknown]: the triplets (5 of 16 bytes),
// the matrix, its symmetric copy for the ordering and its permuted copy (5 entries of 12 bytes
// and a column start each), the minimum degree ordering's workspace (about 100 bytes), the
// right-hand side, the solution, the permutations and the elimination tree; rounded up. The
// factor adds 12 bytes per nonzero. Checked against the peak resident size of fills in the tests.
constexpr double bytes_per_unknown = 512.0;
constexpr double bytes_per_factor_nonzero = 12.0;

// The unknowns' numbers: -1 at known points, 0, 1, ... at the missing ones (x fastest).
std::vector<Index> number_missing(const Field& heights, Index& unknowns) {
  std::vector<Index> number(static_cast<std::size_t>(heights.size()), -1);
  unknowns = 0;
  for (Index k = 0; k < heights.size(); ++k)
    if (std::isnan(heights.data()[k])) number[static_cast<std::size_t>(k)] = unknowns++;
  return number;
}

// Multiply-adds per unknown and point of thickness of the factorisation of one hole: 16 to 21
// measured on square holes of 512^2 and 768^2 points in minimum degree order (nested dissection
// needs about k^3 for a k x k hole: George 1973).
constexpr double operations_per_point_thickness = 16.0;

// An estimate of the factorisation's multiply-adds, before anything of size the fill is made:
// for each hole (4-connected missing points), its count h times its mean thickness (h over the
// longer side of its bounding box), times operations_per_point_thickness. Short of the exact
// count for compact holes (so a refusal on it is sure), and small for scratches and rings,
// whose factors are small.
double estimated_operations(const Field& heights, const std::vector<Index>& number) {
  const Index nx = heights.rows(), ny = heights.cols();
  std::vector<bool> seen(number.size(), false);
  std::vector<Index> stack;
  double total = 0;
  for (Index start = 0; start < heights.size(); ++start) {
    if (number[static_cast<std::size_t>(start)] < 0 || seen[static_cast<std::size_t>(start)])
      continue;
    Index h = 0, i0 = nx, i1 = 0, j0 = ny, j1 = 0;
    seen[static_cast<std::size_t>(start)] = true;
    stack.push_back(start);
    while (!stack.empty()) {
      const Index k = stack.back(), i = k % nx, j = k / nx;
      stack.pop_back();
      ++h;
      i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
      for (const Index n : {i > 0 ? k - 1 : -1, i + 1 < nx ? k + 1 : -1, j > 0 ? k - nx : -1,
                            j + 1 < ny ? k + nx : -1})
        if (n >= 0 && number[static_cast<std::size_t>(n)] >= 0 &&
            !seen[static_cast<std::size_t>(n)]) {
          seen[static_cast<std::size_t>(n)] = true;
          stack.push_back(n);
        }
    }
    const double longer = static_cast<double>(std::max(i1 - i0, j1 - j0) + 1);
    total +=
        operations_per_point_thickness * static_cast<double>(h) * static_cast<double>(h) / longer;
  }
  return total;
}

// The discrete Laplace equation over the missing points: at each, (its number of neighbours) z
// minus the sum of its neighbours = 0, the known neighbours (divided by `scale`) moved to the
// right-hand side.
struct LaplaceSystem {
  Matrix a;
  Eigen::VectorXd rhs;
};

LaplaceSystem laplace_system(const Field& heights, const std::vector<Index>& number, Index unknowns,
                             double scale) {
  const Index nx = heights.rows(), ny = heights.cols();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(5 * unknowns));
  LaplaceSystem s{Matrix(unknowns, unknowns), Eigen::VectorXd::Zero(unknowns)};
  const Index di[] = {1, -1, 0, 0}, dj[] = {0, 0, 1, -1};
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i) {
      const Index row = number[static_cast<std::size_t>(i + nx * j)];
      if (row < 0) continue;
      double degree = 0;
      for (int d = 0; d < 4; ++d) {
        const Index a = i + di[d], b = j + dj[d];
        if (a < 0 || a >= nx || b < 0 || b >= ny) continue;
        degree += 1;
        const Index col = number[static_cast<std::size_t>(a + nx * b)];
        if (col >= 0)
          entries.emplace_back(row, col, -1.0);
        else
          s.rhs(row) += heights(a, b) / scale;
      }
      entries.emplace_back(row, row, degree);
    }
  s.a.setFromTriplets(entries.begin(), entries.end());
  return s;
}

// The size of the Cholesky factor L of `upper` (the upper triangle of a symmetric matrix, in
// the order it is factorised): its off-diagonal nonzeros and the multiply-adds of the
// factorisation (the sum of the squared column counts), by the elimination tree's row
// subtrees (Liu 1990; the walk of Eigen's SimplicialCholesky), in time proportional to the
// nonzeros counted. The count stops once it passes `max_nonzeros` or `max_flops`.
struct FactorSize {
  double nonzeros = 0, flops = 0;
  bool complete = false;  ///< false: counted up to a bound, the factor is larger
};

FactorSize factor_size(const Matrix& upper, double max_nonzeros, double max_flops) {
  const Index n = upper.cols();
  std::vector<Index> parent(static_cast<std::size_t>(n)), tag(static_cast<std::size_t>(n));
  std::vector<double> count(static_cast<std::size_t>(n), 0.0);
  FactorSize size;
  for (Index k = 0; k < n; ++k) {
    parent[static_cast<std::size_t>(k)] = -1;
    tag[static_cast<std::size_t>(k)] = k;
    for (Matrix::InnerIterator it(upper, k); it; ++it)
      for (Index i = it.index(); i < k && tag[static_cast<std::size_t>(i)] != k;
           i = parent[static_cast<std::size_t>(i)]) {
        const auto u = static_cast<std::size_t>(i);
        if (parent[u] == -1) parent[u] = k;
        size.flops += 2 * count[u] + 1;  // (c + 1)^2 - c^2
        count[u] += 1;
        size.nonzeros += 1;
        tag[u] = k;
      }
    if (size.nonzeros > max_nonzeros || size.flops > max_flops) return size;
  }
  size.complete = true;
  return size;
}

// Refuses a fill beyond the memory limit (the map's reading's: --max-memory, else what the
// machine has) or beyond max_fill_operations, naming the count of missing points; before the
// factor is counted, on what the fill takes besides it.
void require_fill_bounds(std::string_view where, Index unknowns,
                         const std::optional<FactorSize>& factor, std::optional<double> limit) {
  const double nonzeros = factor ? factor->nonzeros : 0.0;
  const std::string drivers = factor
                                  ? detail::concat(unknowns, " missing points (a factor of ",
                                                   factor->complete ? "" : "more than ", nonzeros,
                                                   " nonzeros, counted up to the limit)")
                                  : detail::concat(unknowns, " missing points");
  require_memory(
      {bytes_per_unknown * static_cast<double>(unknowns) + bytes_per_factor_nonzero * nonzeros,
       drivers},
      limit, detail::concat(where, ": filling the missing points"), "--max-memory",
      "measure or crop a map with fewer or smaller holes");
  COATFFT_REQUIRE(!factor || factor->flops <= max_fill_operations, where, ": filling ", unknowns,
                  " missing points takes more than ", max_fill_operations / 1e9,
                  "e9 multiply-adds (a factor of more than ", nonzeros,
                  " nonzeros), the limit: measure or crop a map with fewer or smaller holes");
}
}  // namespace

// The matrix is a graph Laplacian with at least one known neighbour in each connected hole, hence
// symmetric positive definite: a sparse Cholesky factorisation (in the minimum degree order of
// Amestoy, Davis and Duff 1996) solves it exactly. Its factor's size is counted before it is
// made, so that a map of wide holes is refused, not factorised for minutes and gigabytes. The
// heights are divided by a power of two near the largest, exactly, so that no sum overflows.
std::size_t fill_missing_points(Field& heights, std::optional<double> max_memory,
                                std::string_view where) {
  Index unknowns = 0;
  const std::vector<Index> number = number_missing(heights, unknowns);
  if (unknowns == 0) return 0;
  COATFFT_REQUIRE(unknowns < heights.size(), where, ": every point is missing");
  // The sparse matrices count their entries (5 a row) in int.
  constexpr Index max_unknowns = std::numeric_limits<int>::max() / 5;
  COATFFT_REQUIRE(unknowns <= max_unknowns, where, ": ", unknowns,
                  " missing points, more than the ", max_unknowns, " a fill takes");
  const double memory = max_memory
                            ? *max_memory
                            : available_memory().value_or(std::numeric_limits<double>::infinity());
  require_fill_bounds(where, unknowns, std::nullopt, max_memory);
  const double estimate = estimated_operations(heights, number);
  COATFFT_REQUIRE(estimate <= max_fill_operations, where, ": filling ", unknowns,
                  " missing points takes about ", std::round(estimate / 1e8) / 10,
                  "e9 multiply-adds (estimated from the holes' sizes), more than the limit of ",
                  max_fill_operations / 1e9,
                  "e9: measure or crop a map with fewer or smaller holes");
  const double largest = heights.isNaN().select(0.0, heights).abs().maxCoeff();
  const double scale = largest > 0 ? std::exp2(std::ilogb(largest)) : 1.0;
  const LaplaceSystem system = laplace_system(heights, number, unknowns, scale);
  Permutation order;
  Eigen::AMDOrdering<int>()(system.a, order);  // the inverse permutation
  Matrix upper(unknowns, unknowns);
  upper.selfadjointView<Eigen::Upper>() =
      system.a.selfadjointView<Eigen::Lower>().twistedBy(order.inverse());
  const double spare = memory - bytes_per_unknown * static_cast<double>(unknowns);
  require_fill_bounds(where, unknowns,
                      factor_size(upper, spare / bytes_per_factor_nonzero, max_fill_operations),
                      max_memory);
  const Eigen::SimplicialLDLT<Matrix, Eigen::Upper, Eigen::NaturalOrdering<int>> solver(upper);
  // A hole's points are connected to a known one through the map (the map has a known point and
  // is connected), so the factorisation cannot fail; checked all the same.
  COATFFT_REQUIRE(solver.info() == Eigen::Success, where,
                  ": the missing points could not be filled");
  const Eigen::VectorXd filled = order * solver.solve(order.inverse() * system.rhs);
  // Exact up to rounding: each equation holds to fill_tolerance of the largest height.
  const double residual = (system.a * filled - system.rhs).lpNorm<Eigen::Infinity>();
  COATFFT_REQUIRE(residual <= fill_tolerance * 8.0 * largest / scale, where,
                  ": the fill of the missing points is off by ", residual * scale,
                  " m in the harmonic rule");
  for (Index k = 0; k < heights.size(); ++k) {
    const Index n = number[static_cast<std::size_t>(k)];
    if (n >= 0) heights.data()[k] = filled(n) * scale;
  }
  return static_cast<std::size_t>(unknowns);
}

}  // namespace coatfft::topography
