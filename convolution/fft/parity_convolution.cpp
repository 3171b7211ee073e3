#include "convolution/fft/parity_convolution.hpp"

#include <algorithm>
#include <complex>
#include <utility>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/fft/parity_transform.hpp"
#include "core/detail/fft_size.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace coatfft {

// The padded transforms pruned and blocked as in DcfftOperator: the x transforms run on the ny
// data rows only (the padding rows are zero on input and not wanted on output), in place; the y
// transforms on cache-sized blocks of columns gathered contiguous. The loads' spectra are kept
// column-major, [kx][ky], so that each block of a component is formed in place from them. A
// plane's six inverse transforms then cost about three surface applications.
struct ParityConvolution::Transforms {
  FftwComplexBuffer rows;                 // (ny, hx); its real view has row stride 2 hx
  std::array<FftwComplexBuffer, 3> load;  // (hx, my) spectra of the loads, column-major
  std::array<bool, 3> present{};          // loads given to apply()
  FftwComplexBuffer block;                // (block_cols, my) columns
  std::ptrdiff_t block_cols = 1;
  FftwPlan forward_x, backward_x;  // in place on rows
  FftwPlan forward_y, backward_y;  // in place on block
};

namespace {

// The spectrum quarter (hx, hy) of one coefficient quarter, with FFTW's 1/(mx my) folded in:
// zero-padded, or, for periodic coefficients (nx, ny), their offsets 0..nx/2, 0..ny/2 (the rest
// follows by the parity).
Field padded_spectrum(const Field& coefficients, std::ptrdiff_t hx, std::ptrdiff_t hy,
                      std::array<bool, 2> odd, double scale) {
  Field quarter = Field::Zero(hx, hy);
  const std::ptrdiff_t rows = std::min(hx, coefficients.rows());
  const std::ptrdiff_t cols = std::min(hy, coefficients.cols());
  quarter.topLeftCorner(rows, cols) = coefficients.topLeftCorner(rows, cols);
  // Transposed to (hy, hx): apply() reads it along ky.
  return scale * parity_transform(quarter, odd[0], odd[1]).transpose();
}

}  // namespace

ParityConvolution::ParityConvolution(const Grid& grid, int nb_loads, Planning planning,
                                     bool periodic)
    : grid_(grid), nb_loads_(nb_loads), periodic_(periodic) {
  if (nb_loads < 1 || nb_loads > 3) throw InvalidArgument("parity convolution: 1 to 3 loads");
  COATFFT_REQUIRE(!periodic || (grid.nx() % 2 == 0 && grid.ny() % 2 == 0),
                  "parity convolution: a periodic grid needs nx and ny even");
  // Any period >= 2n - 1 keeps the offsets -(n - 1)..n - 1 apart (DC-FFT); even, for the parity
  // transforms, and 7-smooth, for FFTW (core/detail/fft_size.hpp). A periodic surface's period is
  // the grid's own.
  mx_ = periodic ? grid_.nx() : detail::fast_even_fft_size(2 * grid_.nx() - 1);
  my_ = periodic ? grid_.ny() : detail::fast_even_fft_size(2 * grid_.ny() - 1);
  hx_ = mx_ / 2 + 1;
  hy_ = my_ / 2 + 1;
  plan_transforms(planning);
}

ParityConvolution::~ParityConvolution() = default;
ParityConvolution::ParityConvolution(ParityConvolution&&) noexcept = default;
ParityConvolution& ParityConvolution::operator=(ParityConvolution&&) noexcept = default;

void ParityConvolution::add_output(std::span<const ParityKernel> kernels) {
  if (static_cast<int>(kernels.size()) != nb_loads_)
    throw InvalidArgument("parity convolution: one kernel per load");
  const double scale = 1.0 / (static_cast<double>(mx_) * static_cast<double>(my_));
  std::vector<Field> spectra;
  std::vector<std::array<bool, 2>> odd;
  for (const ParityKernel& k : kernels) {
    if (k.quarter.size() != 0 && (k.quarter.rows() != grid_.nx() || k.quarter.cols() != grid_.ny()))
      throw InvalidArgument("parity convolution: a kernel's shape is not the grid's (nx, ny)");
    spectra.push_back(k.quarter.size() == 0
                          ? Field()
                          : padded_spectrum(k.quarter, hx_, hy_, {k.odd_x, k.odd_y}, scale));
    odd.push_back({k.odd_x, k.odd_y});
  }
  spectra_.push_back(std::move(spectra));
  odd_.push_back(std::move(odd));
}

void ParityConvolution::add_spectral_output(std::span<const ParitySpectrum> spectra) {
  COATFFT_REQUIRE(static_cast<int>(spectra.size()) == nb_loads_,
                  "parity convolution: one spectrum per load");
  const double scale = 1.0 / (static_cast<double>(mx_) * static_cast<double>(my_));
  std::vector<Field> stored;
  std::vector<std::array<bool, 2>> odd;
  for (const ParitySpectrum& s : spectra) {
    COATFFT_REQUIRE(s.quarter.size() == 0 || (s.quarter.rows() == hx_ && s.quarter.cols() == hy_),
                    "parity convolution: a spectrum's shape is not the lattice quarter (", hx_,
                    ", ", hy_, ")");
    COATFFT_REQUIRE(s.quarter.allFinite(), "parity convolution: a spectrum holds NaN or Inf");
    // Transposed to (hy, hx) as add_output's, FFTW's 1/(mx my) folded in.
    stored.push_back(s.quarter.size() == 0 ? Field() : Field(scale * s.quarter.transpose()));
    odd.push_back({s.odd_x, s.odd_y});
  }
  spectra_.push_back(std::move(stored));
  odd_.push_back(std::move(odd));
}

void ParityConvolution::plan_transforms(Planning planning) {
  transforms_ = std::make_unique<Transforms>();
  Transforms& t = *transforms_;
  const std::ptrdiff_t ny = grid_.ny();
  t.rows = FftwComplexBuffer(static_cast<std::size_t>(ny * hx_));
  for (int l = 0; l < nb_loads_; ++l)
    t.load[l] = FftwComplexBuffer(static_cast<std::size_t>(hx_ * my_));
  // About 64 KiB of columns per block, as DcfftOperator.
  t.block_cols = std::clamp<std::ptrdiff_t>(64 * 1024 / (my_ * 16), 1, hx_);
  t.block = FftwComplexBuffer(static_cast<std::size_t>(t.block_cols * my_));
  const unsigned flags = fftw_flags(planning);
  const int mx = static_cast<int>(mx_), my = static_cast<int>(my_), hx = static_cast<int>(hx_);
  const int n_x[1] = {mx}, n_y[1] = {my}, bw = static_cast<int>(t.block_cols);
  double* real = reinterpret_cast<double*>(t.rows.data());
  fftw_complex* rows = t.rows.data();
  fftw_complex* block = t.block.data();
  t.forward_x = FftwPlan::create(1, [&] {
    return fftw_plan_many_dft_r2c(1, n_x, static_cast<int>(ny), real, nullptr, 1, 2 * hx, rows,
                                  nullptr, 1, hx, flags);
  });
  t.backward_x = FftwPlan::create(1, [&] {
    return fftw_plan_many_dft_c2r(1, n_x, static_cast<int>(ny), rows, nullptr, 1, hx, real, nullptr,
                                  1, 2 * hx, flags);
  });
  for (auto [plan, sign] : {std::pair{&t.forward_y, FFTW_FORWARD}, {&t.backward_y, FFTW_BACKWARD}})
    *plan = FftwPlan::create(1, [&, sign = sign] {
      return fftw_plan_many_dft(1, n_y, bw, block, nullptr, 1, my, block, nullptr, 1, my, sign,
                                flags);
    });
}

void ParityConvolution::transform_load(int load, const Field* field) {
  Transforms& t = *transforms_;
  t.present[load] = field != nullptr;
  if (!field) return;
  if (field->rows() != grid_.nx() || field->cols() != grid_.ny())
    throw InvalidArgument("parity convolution: a load's shape is not the grid's (nx, ny)");
  if (!field->allFinite()) throw InvalidArgument("parity convolution: a load holds NaN or Inf");
  const std::ptrdiff_t nx = grid_.nx(), ny = grid_.ny();
  double* real = reinterpret_cast<double*>(t.rows.data());
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    double* row = real + j * 2 * hx_;
    for (std::ptrdiff_t i = 0; i < nx; ++i) row[i] = (*field)(i, j);
    std::fill(row + nx, row + 2 * hx_, 0.0);
  }
  t.forward_x.execute();
  const auto* rows = as_complex(t.rows.data());
  auto* block = as_complex(t.block.data());
  auto* spectrum = as_complex(t.load[load].data());
  for (std::ptrdiff_t c0 = 0; c0 < hx_; c0 += t.block_cols) {
    const std::ptrdiff_t width = std::min(t.block_cols, hx_ - c0);
    std::fill(block, block + t.block_cols * my_, std::complex<double>{});
    for (std::ptrdiff_t ky = 0; ky < ny; ++ky)
      for (std::ptrdiff_t c = 0; c < width; ++c) block[c * my_ + ky] = rows[ky * hx_ + c0 + c];
    t.forward_y.execute();
    std::copy(block, block + width * my_, spectrum + c0 * my_);
  }
}

namespace {

// w[i] += (-i)^Q k[i] s[i] for complex w, s (as pairs of doubles) and real k, i in [0, n); and
// the same with k read backwards from k_end (k_end[-i]): the mirrored rows ky > my/2. Plain real
// arithmetic: a complex product would check for NaN at every element.
template <int Q>
void accumulate(double* w, const double* k, int step, const double* s, std::ptrdiff_t n) {
  for (std::ptrdiff_t i = 0; i < n; ++i, k += step) {
    const double a = *k * s[2 * i], b = *k * s[2 * i + 1];
    if constexpr (Q == 0) {
      w[2 * i] += a, w[2 * i + 1] += b;
    } else if constexpr (Q == 1) {
      w[2 * i] += b, w[2 * i + 1] -= a;
    } else if constexpr (Q == 2) {
      w[2 * i] -= a, w[2 * i + 1] -= b;
    } else {
      w[2 * i] -= b, w[2 * i + 1] += a;
    }
  }
}

void accumulate(int quarter_turns, double* w, const double* k, int step, const double* s,
                std::ptrdiff_t n) {
  switch (quarter_turns % 4) {
    case 0:
      return accumulate<0>(w, k, step, s, n);
    case 1:
      return accumulate<1>(w, k, step, s, n);
    case 2:
      return accumulate<2>(w, k, step, s, n);
    default:
      return accumulate<3>(w, k, step, s, n);
  }
}

}  // namespace

// The block of columns c0.. of one component: the sum over the loads of its padded spectrum times
// the load's. The stored quarter R, (hy, hx), gives (-i)^(odd_x + odd_y) R(|ky|, kx), with R's
// sign flipped (two more quarter turns) for ky < 0 when odd in y.
void ParityConvolution::multiply_block(std::size_t output, std::ptrdiff_t c0,
                                       std::ptrdiff_t width) {
  Transforms& t = *transforms_;
  auto* block = reinterpret_cast<double*>(t.block.data());
  std::fill(block, block + 2 * t.block_cols * my_, 0.0);
  const std::ptrdiff_t half = my_ / 2;
  for (int l = 0; l < nb_loads_; ++l) {
    if (!t.present[l]) continue;
    const Field& r = spectra_[output][l];
    if (r.size() == 0) continue;
    const auto odd = odd_[output][l];
    const int turns = int(odd[0]) + int(odd[1]);
    const int mirrored_turns = turns + (odd[1] ? 2 : 0);
    const auto* in = reinterpret_cast<const double*>(t.load[l].data());
    for (std::ptrdiff_t c = 0; c < width; ++c) {
      const double* k = &r(0, c0 + c);
      const double* s = in + 2 * (c0 + c) * my_;
      double* w = block + 2 * c * my_;
      accumulate(turns, w, k, 1, s, half + 1);
      accumulate(mirrored_turns, w + 2 * (half + 1), k + (my_ - half - 1), -1, s + 2 * (half + 1),
                 my_ - half - 1);
    }
  }
}

void ParityConvolution::inverse_into(std::size_t output, Field& out) {
  Transforms& t = *transforms_;
  const std::ptrdiff_t nx = grid_.nx(), ny = grid_.ny();
  auto* rows = as_complex(t.rows.data());
  const auto* block = as_complex(t.block.data());
  for (std::ptrdiff_t c0 = 0; c0 < hx_; c0 += t.block_cols) {
    const std::ptrdiff_t width = std::min(t.block_cols, hx_ - c0);
    multiply_block(output, c0, width);
    t.backward_y.execute();
    // Only the rows ky < ny of the inverse are inside the crop.
    for (std::ptrdiff_t ky = 0; ky < ny; ++ky)
      for (std::ptrdiff_t c = 0; c < width; ++c) rows[ky * hx_ + c0 + c] = block[c * my_ + ky];
  }
  t.backward_x.execute();
  const double* real = reinterpret_cast<const double*>(t.rows.data());
  out.resize(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) out(i, j) = real[j * 2 * hx_ + i];
}

void ParityConvolution::apply(std::span<const Field* const> loads, std::vector<Field>& out,
                              std::size_t first) {
  if (static_cast<int>(loads.size()) != nb_loads_)
    throw InvalidArgument("parity convolution: one field (or null) per load");
  for (int l = 0; l < nb_loads_; ++l) transform_load(l, loads[l]);
  out.resize(spectra_.size());
  // Many planes make many outputs. Stopping between two is safe: every apply starts afresh.
  for (std::size_t o = 0; o < std::min(first, spectra_.size()); ++o) {
    check_interrupt();
    inverse_into(o, out[o]);
  }
}

std::size_t ParityConvolution::memory_bytes() const {
  std::size_t bytes = 0;
  for (const auto& output : spectra_)
    for (const Field& f : output) bytes += static_cast<std::size_t>(f.size()) * sizeof(double);
  const auto complex_size = static_cast<std::size_t>(my_ * hx_) * 16;
  return bytes + static_cast<std::size_t>(grid_.ny() * hx_) * 16 +
         static_cast<std::size_t>(nb_loads_) * complex_size +
         static_cast<std::size_t>(transforms_->block_cols * my_) * 16;
}

}  // namespace coatfft
