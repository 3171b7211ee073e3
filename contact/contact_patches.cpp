#include "contact/detail/contact_patches.hpp"

#include <array>
#include <vector>

namespace coatfft::detail {

int count_patches(const CellMask& cells, bool periodic) {
  const auto nx = cells.rows(), ny = cells.cols();
  CellMask seen = CellMask::Constant(nx, ny, false);
  std::vector<std::array<std::ptrdiff_t, 2>> stack;
  int patches = 0;
  // The neighbour at (i + di, j + dj), wrapped on a periodic grid; false beyond a free edge.
  const auto visit = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    if (periodic) {
      i = (i + nx) % nx;
      j = (j + ny) % ny;
    } else if (i < 0 || i >= nx || j < 0 || j >= ny) {
      return;
    }
    if (cells(i, j) && !seen(i, j)) {
      seen(i, j) = true;
      stack.push_back({i, j});
    }
  };
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      if (!cells(i, j) || seen(i, j)) continue;
      ++patches;
      visit(i, j);
      while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        visit(a - 1, b);
        visit(a + 1, b);
        visit(a, b - 1);
        visit(a, b + 1);
      }
    }
  }
  return patches;
}

}  // namespace coatfft::detail
