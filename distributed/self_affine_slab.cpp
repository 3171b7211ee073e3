#include "distributed/self_affine_slab.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "distributed/detail/slab_fft.hpp"
#include "surfaces/detail/self_affine_spectrum.hpp"

namespace coatfft {

namespace {

using detail::SpectrumMoments;

// Every row's moments on every rank: each rank fills its rows and the sum over the ranks adds
// only zeros to them, so the rows' sum in row order is the serial one bit for bit.
std::vector<SpectrumMoments> all_row_moments(const Communicator& comm, const Grid& g,
                                             const SelfAffineSpec& spec, const Slab& s) {
  const std::vector<SpectrumMoments> mine =
      detail::self_affine_row_moments(g, spec, s.y0, s.y0 + s.rows);
  std::vector<double> all(2 * static_cast<std::size_t>(g.ny()), 0.0);
  for (std::size_t r = 0; r < mine.size(); ++r) {
    all[2 * (static_cast<std::size_t>(s.y0) + r)] = mine[r].height2;
    all[2 * (static_cast<std::size_t>(s.y0) + r) + 1] = mine[r].slope2;
  }
  comm.sum(all);
  std::vector<SpectrumMoments> rows(static_cast<std::size_t>(g.ny()));
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = {all[2 * r], all[2 * r + 1]};
  return rows;
}

}  // namespace

double spectral_rms_slope(const Communicator& comm, const Grid& g, const Field& rows) {
  detail::SlabFft fft(comm, g.nx(), g.ny());
  const Slab& s = fft.slab();
  COATFFT_REQUIRE(comm.all(rows.rows() == s.nx && rows.cols() == s.rows),
                  "spectral_rms_slope: a rank's rows are not of its slab's shape");
  fft.forward(rows.data());
  // Parseval over this rank's half-spectrum columns, as spectral_rms_slope over the whole.
  const double cells = static_cast<double>(g.nb_cells());
  double sum = 0.0;
  for (std::ptrdiff_t c = 0; c < s.columns; ++c)
    for (std::ptrdiff_t j = 0; j < s.ny; ++j)
      sum += detail::mode_slope2(g, s.kx0 + c, j, fft.spectrum()[c * s.ny + j]) / (cells * cells);
  return std::sqrt(comm.sum(sum));
}

Field self_affine_slab(const Communicator& comm, const Grid& grid, const SelfAffineSpec& spec) {
  const Slab s = slab_of(comm, grid.nx(), grid.ny());
  const double scale = detail::self_affine_scale(spec, all_row_moments(comm, grid, spec, s));
  detail::SlabFft fft(comm, grid.nx(), grid.ny());
  detail::self_affine_rows(grid, spec, s.y0, s.y0 + s.rows, fft.row_spectrum());
  Field h = s.field();
  fft.inverse_from_rows(h.data());
  return h * scale;
}

}  // namespace coatfft
