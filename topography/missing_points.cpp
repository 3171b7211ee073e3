#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "topography/topography.hpp"

namespace coatfft::topography {

namespace {
using Index = Eigen::Index;

// The unknowns' numbers: -1 at known points, 0, 1, ... at the missing ones (x fastest).
std::vector<Index> number_missing(const Field& heights) {
  std::vector<Index> number(static_cast<std::size_t>(heights.size()), -1);
  Index count = 0;
  for (Index k = 0; k < heights.size(); ++k)
    if (std::isnan(heights.data()[k])) number[static_cast<std::size_t>(k)] = count++;
  return number;
}
}  // namespace

// The discrete Laplace equation over the missing points: at each, (its number of neighbours) z
// minus the sum of its neighbours = 0, the known neighbours moved to the right-hand side. The
// matrix is a graph Laplacian with at least one known neighbour in each connected hole, hence
// symmetric positive definite: a sparse Cholesky factorisation solves it exactly.
std::size_t fill_missing_points(Field& heights) {
  const std::vector<Index> number = number_missing(heights);
  Index unknowns = 0;
  for (const Index n : number) unknowns += n >= 0;
  if (unknowns == 0) return 0;
  COATFFT_REQUIRE(unknowns < heights.size(), "every point of the topography is missing");
  const Index nx = heights.rows(), ny = heights.cols();
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
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
          rhs(row) += heights(a, b);
      }
      entries.emplace_back(row, row, degree);
    }
  Eigen::SparseMatrix<double> laplacian(unknowns, unknowns);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  // A hole's points are connected to a known one through the map (the map has a known point and
  // is connected), so the factorisation cannot fail; checked all the same.
  COATFFT_REQUIRE(solver.info() == Eigen::Success, "the missing points could not be filled");
  const Eigen::VectorXd filled = solver.solve(rhs);
  for (Index k = 0; k < heights.size(); ++k) {
    const Index n = number[static_cast<std::size_t>(k)];
    if (n >= 0) heights.data()[k] = filled(n);
  }
  return static_cast<std::size_t>(unknowns);
}

}  // namespace coatfft::topography
