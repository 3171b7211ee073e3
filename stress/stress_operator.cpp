#include "stress/stress_operator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <utility>

#include "convolution/fftw_plan.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/fft_size.hpp"
#include "frf/stress_frf.hpp"
#include "stress/parity_transform.hpp"

namespace coatfft {

// The padded transforms pruned and blocked as in DcfftOperator: the x transforms run on the ny
// data rows only (the padding rows are zero on input and not wanted on output), in place; the y
// transforms on cache-sized blocks of columns gathered contiguous. The loads' spectra are kept
// column-major, [kx][ky], so that each block of a component is formed in place from them. A
// plane's six inverse transforms then cost about three surface applications.
struct StressOperator::Transforms {
  FftwComplexBuffer rows;                 // (ny, hx); its real view has row stride 2 hx
  std::array<FftwComplexBuffer, 3> load;  // (hx, my) spectra of the loads, column-major
  std::array<bool, 3> present{};          // loads given to apply()
  FftwComplexBuffer block;                // (block_cols, my) columns
  std::ptrdiff_t block_cols = 1;
  FftwPlan forward_x, backward_x;  // in place on rows
  FftwPlan forward_y, backward_y;  // in place on block
};

namespace {

void validate_depths(const std::vector<double>& depths) {
  if (depths.empty()) throw InvalidArgument("stress operator: no depth given");
  for (double z : depths)
    if (!std::isfinite(z) || z < 0.0)
      throw InvalidArgument("stress operator: every depth must be finite and >= 0 [m]");
}

void refuse_sliding_tangential(const LayerStack& stack) {
  for (std::size_t i = 0; i < stack.coatings().size(); ++i)
    if (stack.coatings()[i].interface_below == Interface::frictionless)
      throw InvalidArgument(
          "stress operator: tangential tractions on a body with a frictionless "
          "interface (below coating " +
          std::to_string(i + 1) +
          ") are not supported: a net tangential force has no equilibrium "
          "there");
}

// The padded spectrum quarter of one coefficient quarter, with FFTW's 1/(mx my) folded in.
Field padded_spectrum(const Field& coefficients, std::ptrdiff_t hx, std::ptrdiff_t hy,
                      std::array<bool, 2> odd, double scale) {
  Field quarter = Field::Zero(hx, hy);
  quarter.topLeftCorner(coefficients.rows(), coefficients.cols()) = coefficients;
  // Transposed to (hy, hx): apply() reads it along ky.
  return scale * parity_transform(quarter, odd[0], odd[1]).transpose();
}

}  // namespace

StressOperator::StressOperator(const Grid& grid, const LayerStack& stack,
                               std::vector<double> depths, const StressOperatorOptions& options)
    : grid_(grid),
      depths_(std::move(depths)),
      tangential_(options.tangential),
      nb_loads_(options.tangential ? 3 : 1) {
  const auto start = std::chrono::steady_clock::now();
  validate_depths(depths_);
  if (tangential_) refuse_sliding_tangential(stack);
  // Any period >= 2n - 1 keeps the offsets -(n - 1)..n - 1 apart (DC-FFT); even, for the parity
  // transforms, and 7-smooth, for FFTW (core/fft_size.hpp).
  mx_ = fast_even_fft_size(2 * grid_.nx() - 1);
  my_ = fast_even_fft_size(2 * grid_.ny() - 1);
  hx_ = mx_ / 2 + 1;
  hy_ = my_ / 2 + 1;
  const double scale = 1.0 / (static_cast<double>(mx_) * static_cast<double>(my_));
  // The planes' kernels are made in groups: one FRF solve per wavevector serves a group, and
  // a group's lattice quarters (six per plane) bound the memory.
  constexpr std::size_t kGroup = 8;
  for (std::size_t first = 0; first < depths_.size(); first += kGroup) {
    const std::size_t count = std::min(kGroup, depths_.size() - first);
    std::vector<StressKernelReport> reports;
    const std::vector<StressPlaneKernel> kernels =
        stress_plane_kernels(grid_, stack, std::span<const double>(depths_).subspan(first, count),
                             options.side, tangential_, options.kernel, &reports);
    for (const StressPlaneKernel& kernel : kernels) {
      auto& plane = spectra_.emplace_back();
      for (int c = 0; c < 6; ++c)
        for (int l = 0; l < nb_loads_; ++l)
          plane[c][l] =
              padded_spectrum(kernel.coefficients[c][l], hx_, hy_, stress_frf_odd(c, l), scale);
    }
    reports_.insert(reports_.end(), reports.begin(), reports.end());
  }
  plan_transforms(options.planning);
  setup_seconds_ = detail::seconds_since(start);
}

StressOperator::~StressOperator() = default;
StressOperator::StressOperator(StressOperator&&) noexcept = default;
StressOperator& StressOperator::operator=(StressOperator&&) noexcept = default;

void StressOperator::plan_transforms(Planning planning) {
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

void StressOperator::transform_load(int load, const Field* field) {
  Transforms& t = *transforms_;
  t.present[load] = field != nullptr;
  if (!field) return;
  if (field->rows() != grid_.nx() || field->cols() != grid_.ny())
    throw InvalidArgument("stress operator: a load's shape is not the grid's (nx, ny)");
  if (!field->allFinite()) throw InvalidArgument("stress operator: a load holds NaN or Inf");
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
void StressOperator::multiply_block(int plane, int component, std::ptrdiff_t c0,
                                    std::ptrdiff_t width) {
  Transforms& t = *transforms_;
  auto* block = reinterpret_cast<double*>(t.block.data());
  std::fill(block, block + 2 * t.block_cols * my_, 0.0);
  const std::ptrdiff_t half = my_ / 2;
  for (int l = 0; l < nb_loads_; ++l) {
    if (!t.present[l]) continue;
    const auto odd = stress_frf_odd(component, l);
    const int turns = int(odd[0]) + int(odd[1]);
    const int mirrored_turns = turns + (odd[1] ? 2 : 0);
    const Field& r = spectra_[plane][component][l];
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

void StressOperator::inverse_into(int plane, int component, Field& out) {
  Transforms& t = *transforms_;
  const std::ptrdiff_t nx = grid_.nx(), ny = grid_.ny();
  auto* rows = as_complex(t.rows.data());
  const auto* block = as_complex(t.block.data());
  for (std::ptrdiff_t c0 = 0; c0 < hx_; c0 += t.block_cols) {
    const std::ptrdiff_t width = std::min(t.block_cols, hx_ - c0);
    multiply_block(plane, component, c0, width);
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

void StressOperator::apply(const Field& pressure, const Field* qx, const Field* qy,
                           std::vector<PlaneStress>& stress) {
  if (!tangential_ && (qx || qy))
    throw InvalidArgument(
        "stress operator: tractions given to an operator built for pressure only");
  transform_load(load_p, &pressure);
  if (tangential_) {
    transform_load(load_qx, qx);
    transform_load(load_qy, qy);
  }
  stress.resize(depths_.size());
  for (std::size_t plane = 0; plane < depths_.size(); ++plane)
    for (int c = 0; c < 6; ++c) inverse_into(static_cast<int>(plane), c, stress[plane][c]);
}

std::size_t StressOperator::memory_bytes() const {
  const auto quarter = static_cast<std::size_t>(hx_ * hy_) * sizeof(double);
  const auto complex_size = static_cast<std::size_t>(my_ * hx_) * 16;
  return spectra_.size() * 6 * static_cast<std::size_t>(nb_loads_) * quarter +
         static_cast<std::size_t>(grid_.ny() * hx_) * 16 +
         static_cast<std::size_t>(nb_loads_) * complex_size +
         static_cast<std::size_t>(transforms_->block_cols * my_) * 16;
}

}  // namespace coatfft
