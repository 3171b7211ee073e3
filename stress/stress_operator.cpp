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

struct StressOperator::Transforms {
  FftwRealBuffer real;                    // (my, mx) padded load, then one stress component
  std::array<FftwComplexBuffer, 3> load;  // (my, hx) spectra of the loads
  std::array<bool, 3> present{};          // loads given to apply()
  FftwComplexBuffer work;                 // (my, hx) spectrum of one stress component
  std::array<FftwPlan, 3> forward;        // real -> load[l]
  FftwPlan backward;                      // work -> real
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
  return scale * parity_transform(quarter, odd[0], odd[1]);
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
  const auto complex_size = static_cast<std::size_t>(my_ * hx_);
  t.real = FftwRealBuffer(static_cast<std::size_t>(my_ * mx_));
  for (int l = 0; l < nb_loads_; ++l) t.load[l] = FftwComplexBuffer(complex_size);
  t.work = FftwComplexBuffer(complex_size);
  const unsigned flags = fftw_flags(planning);
  const int my = static_cast<int>(my_), mx = static_cast<int>(mx_);
  for (int l = 0; l < nb_loads_; ++l)
    t.forward[l] = FftwPlan::create(
        1, [&] { return fftw_plan_dft_r2c_2d(my, mx, t.real.data(), t.load[l].data(), flags); });
  t.backward = FftwPlan::create(
      1, [&] { return fftw_plan_dft_c2r_2d(my, mx, t.work.data(), t.real.data(), flags); });
}

void StressOperator::transform_load(int load, const Field* field) {
  Transforms& t = *transforms_;
  t.present[load] = field != nullptr;
  if (!field) return;
  if (field->rows() != grid_.nx() || field->cols() != grid_.ny())
    throw InvalidArgument("stress operator: a load's shape is not the grid's (nx, ny)");
  if (!field->allFinite()) throw InvalidArgument("stress operator: a load holds NaN or Inf");
  double* r = t.real.data();
  std::fill(r, r + my_ * mx_, 0.0);
  for (std::ptrdiff_t j = 0; j < grid_.ny(); ++j)
    for (std::ptrdiff_t i = 0; i < grid_.nx(); ++i) r[j * mx_ + i] = (*field)(i, j);
  t.forward[load].execute();
}

// work = sum over the loads of the component's padded spectrum times the load's: the stored
// quarter R gives (-i)^(odd_x + odd_y) R(kx, |ky|), with R's sign flipped for ky < 0 when odd in y.
void StressOperator::multiply_spectra(int plane, int component) {
  Transforms& t = *transforms_;
  auto* work = as_complex(t.work.data());
  std::fill(work, work + my_ * hx_, std::complex<double>{});
  for (int l = 0; l < nb_loads_; ++l) {
    if (!t.present[l]) continue;
    const auto odd = stress_frf_odd(component, l);
    const int n_odd = int(odd[0]) + int(odd[1]);
    const std::complex<double> phase = n_odd == 0   ? 1.0
                                       : n_odd == 1 ? std::complex<double>(0, -1)
                                                    : -1.0;
    const Field& r = spectra_[plane][component][l];
    const auto* in = as_complex(t.load[l].data());
    for (std::ptrdiff_t jy = 0; jy < my_; ++jy) {
      const bool negative = jy > my_ / 2;
      const std::ptrdiff_t jq = negative ? my_ - jy : jy;
      const std::complex<double> f = (negative && odd[1]) ? -phase : phase;
      for (std::ptrdiff_t jx = 0; jx < hx_; ++jx)
        work[jy * hx_ + jx] += f * r(jx, jq) * in[jy * hx_ + jx];
    }
  }
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
  const double* r = transforms_->real.data();
  for (std::size_t plane = 0; plane < depths_.size(); ++plane)
    for (int c = 0; c < 6; ++c) {
      multiply_spectra(static_cast<int>(plane), c);
      transforms_->backward.execute();
      Field& out = stress[plane][c];
      out.resize(grid_.nx(), grid_.ny());
      for (std::ptrdiff_t j = 0; j < grid_.ny(); ++j)
        for (std::ptrdiff_t i = 0; i < grid_.nx(); ++i) out(i, j) = r[j * mx_ + i];
    }
}

std::size_t StressOperator::memory_bytes() const {
  const auto quarter = static_cast<std::size_t>(hx_ * hy_) * sizeof(double);
  const auto complex_size = static_cast<std::size_t>(my_ * hx_) * 16;
  return spectra_.size() * 6 * static_cast<std::size_t>(nb_loads_) * quarter +
         static_cast<std::size_t>(my_ * mx_) * sizeof(double) +
         static_cast<std::size_t>(nb_loads_ + 1) * complex_size;
}

}  // namespace coatfft
