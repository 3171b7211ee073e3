#include "contact/detail/contact_patches.hpp"

#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include "contact/detail/solver_ranks.hpp"

namespace coatfft::detail {

namespace {

using Labels = Eigen::Array<std::int32_t, Eigen::Dynamic, Eigen::Dynamic>;

// Labels 0, 1, ... the patches of `cells` (-1 off them) by a flood fill, linear in the cells,
// wrapping x and y each when asked; returns the number of patches.
int label_patches(const CellMask& cells, bool wrap_x, bool wrap_y, Labels& labels) {
  const auto nx = cells.rows(), ny = cells.cols();
  labels = Labels::Constant(nx, ny, -1);
  std::vector<std::array<std::ptrdiff_t, 2>> stack;
  int patches = 0;
  // The neighbour at (i, j), wrapped where asked; none beyond an edge that is not.
  const auto visit = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    if (wrap_x) i = (i + nx) % nx;
    if (wrap_y) j = (j + ny) % ny;
    if (i < 0 || i >= nx || j < 0 || j >= ny) return;
    if (cells(i, j) && labels(i, j) < 0) {
      labels(i, j) = patches;
      stack.push_back({i, j});
    }
  };
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      if (!cells(i, j) || labels(i, j) >= 0) continue;
      visit(i, j);
      while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        visit(a - 1, b);
        visit(a + 1, b);
        visit(a, b - 1);
        visit(a, b + 1);
      }
      ++patches;
    }
  }
  return patches;
}

// The patches of a grid whose rows the ranks hold: each rank's own, joined across the borders of
// consecutive slabs (and, periodic, of the last and the first) by a union-find over every rank's
// patches, from the labels of each slab's first and last row, which every rank gathers.
int count_over_ranks(const CellMask& cells, bool periodic, const SolverRanks& ranks) {
  const auto nx = cells.rows();
  Labels labels;
  const int mine = label_patches(cells, periodic, false, labels);
  // [patches, rows, first row's labels, last row's labels]
  std::vector<std::int32_t> border(static_cast<std::size_t>(2 + 2 * nx), -1);
  border[0] = mine;
  border[1] = static_cast<std::int32_t>(cells.cols());
  if (cells.cols() > 0)
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      border[static_cast<std::size_t>(2 + i)] = labels(i, 0);
      border[static_cast<std::size_t>(2 + nx + i)] = labels(i, cells.cols() - 1);
    }
  const auto size = border.size();
  std::vector<std::int32_t> all(size * static_cast<std::size_t>(ranks.count()));
  ranks.all_gather(border.data(), size * sizeof(std::int32_t), all.data());
  // Each rank's patches numbered after the ranks' before it.
  std::vector<int> first_id, holding;  // per rank; the ranks with rows, in order
  int total = 0;
  for (int r = 0; r < ranks.count(); ++r) {
    first_id.push_back(total);
    total += all[static_cast<std::size_t>(r) * size];
    if (all[static_cast<std::size_t>(r) * size + 1] > 0) holding.push_back(r);
  }
  std::vector<int> parent(static_cast<std::size_t>(total));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  int patches = total;
  // Joins rank a's last row to rank b's first row.
  const auto join = [&](int a, int b) {
    const std::int32_t* last = all.data() + static_cast<std::size_t>(a) * size + 2 + nx;
    const std::int32_t* first = all.data() + static_cast<std::size_t>(b) * size + 2;
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      if (last[i] < 0 || first[i] < 0) continue;
      const int u = root(first_id[a] + last[i]), v = root(first_id[b] + first[i]);
      if (u != v) parent[u] = v, --patches;
    }
  };
  for (std::size_t k = 1; k < holding.size(); ++k) join(holding[k - 1], holding[k]);
  if (periodic && !holding.empty()) join(holding.back(), holding.front());
  return patches;
}

}  // namespace

int count_patches(const CellMask& cells, bool periodic, const SolverRanks* ranks) {
  if (ranks) return count_over_ranks(cells, periodic, *ranks);
  Labels labels;
  return label_patches(cells, periodic, periodic, labels);
}

}  // namespace coatfft::detail
