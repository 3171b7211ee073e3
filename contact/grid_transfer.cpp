#include "contact/detail/grid_transfer.hpp"

namespace coatfft::detail {

Field restrict_by_mean(const Field& fine) {
  Field coarse(fine.rows() / 2, fine.cols() / 2);
  for (std::ptrdiff_t j = 0; j < coarse.cols(); ++j) {
    for (std::ptrdiff_t i = 0; i < coarse.rows(); ++i) {
      coarse(i, j) = 0.25 * (fine(2 * i, 2 * j) + fine(2 * i + 1, 2 * j) + fine(2 * i, 2 * j + 1) +
                             fine(2 * i + 1, 2 * j + 1));
    }
  }
  return coarse;
}

Field prolong_by_cell(const Field& coarse) {
  Field fine(2 * coarse.rows(), 2 * coarse.cols());
  for (std::ptrdiff_t j = 0; j < fine.cols(); ++j) {
    for (std::ptrdiff_t i = 0; i < fine.rows(); ++i) fine(i, j) = coarse(i / 2, j / 2);
  }
  return fine;
}

}  // namespace coatfft::detail
