#include "convolution/fft/detail/spectral_filter.hpp"

#include <algorithm>
#include <complex>
#include <type_traits>

#include "convolution/fft/detail/fftw_plan.hpp"

namespace coatfft::detail {

namespace {

template <typename Real>
class BasicSpectralFilter final : public SpectralFilter {
 public:
  static constexpr bool is_double = std::is_same_v<Real, double>;
  using Complex = std::conditional_t<is_double, fftw_complex, fftwf_complex>;
  using Plan = BasicFftwPlan<std::conditional_t<is_double, fftw_plan, fftwf_plan>>;

  // Planned on a field buffer of FFTW's allocator, freed afterwards in double precision (the
  // transforms then run on the callers' arrays: apply()).
  BasicSpectralFilter(const Grid& grid, Planning planning, int threads)
      : SpectralFilter(grid, is_double ? Precision::double_precision : Precision::single),
        nx_(grid.nx()),
        ny_(grid.ny()),
        hx_(grid.nx() / 2 + 1),
        n_real_(static_cast<std::size_t>(nx_ * ny_)),
        field_(n_real_),
        spectrum_(static_cast<std::size_t>(hx_ * ny_)),
        threads_(threads) {
    // Row-major dimensions {ny, nx}: a Field (x fastest) is a C-order (ny, nx) array.
    const int nx = static_cast<int>(nx_), ny = static_cast<int>(ny_);
    const unsigned flags = fftw_flags(planning);
    forward_ = Plan::create(threads, [&] {
      if constexpr (is_double) {
        return fftw_plan_dft_r2c_2d(ny, nx, field_.data(), spectrum_.data(), flags);
      } else {
        return fftwf_plan_dft_r2c_2d(ny, nx, field_.data(), spectrum_.data(), flags);
      }
    });
    inverse_ = Plan::create(threads, [&] {
      if constexpr (is_double) {
        return fftw_plan_dft_c2r_2d(ny, nx, spectrum_.data(), field_.data(), flags);
      } else {
        return fftwf_plan_dft_c2r_2d(ny, nx, spectrum_.data(), field_.data(), flags);
      }
    });
    if constexpr (is_double) {
      planned_alignment_ = fftw_alignment_of(field_.data());
      field_ = FftwBuffer<Real>();
    }
  }

  void apply(const double* in, double* out, const EvenMultiplier& m) override {
    if constexpr (is_double) {
      if (runs_in_place(in, out)) {
        fftw_execute_dft_r2c(forward_.get(), const_cast<double*>(in), spectrum_.data());
        multiply(m);
        fftw_execute_dft_c2r(inverse_.get(), spectrum_.data(), out);
        return;
      }
    }
    if (field_.size() == 0) field_ = FftwBuffer<Real>(n_real_);  // FFTW's allocator: same alignment
    std::copy_n(in, n_real_, field_.data());
    forward_.execute();
    multiply(m);
    inverse_.execute();
    std::copy_n(field_.data(), n_real_, out);
  }

  // Double precision: the filter's own forward transform. Single: a double filter of its own,
  // planned by estimate for this one transform.
  EvenMultiplier even_spectrum(const double* in, double scale) override {
    if constexpr (!is_double) {
      return BasicSpectralFilter<double>(grid(), Planning::estimate, threads_)
          .even_spectrum(in, scale);
    } else {
      if (runs_in_place(in, nullptr)) {
        fftw_execute_dft_r2c(forward_.get(), const_cast<double*>(in), spectrum_.data());
      } else {
        FftwBuffer<double> copy(n_real_);
        std::copy_n(in, n_real_, copy.data());
        fftw_execute_dft_r2c(forward_.get(), copy.data(), spectrum_.data());
      }
      EvenMultiplier m(nx_, ny_);
      const auto* s = as_complex(spectrum_.data());
      for (std::ptrdiff_t j = 0; j < m.hy; ++j)
        for (std::ptrdiff_t i = 0; i < hx_; ++i) m(i, j) = scale * s[j * hx_ + i].real();
      return m;
    }
  }

 private:
  // Whether FFTW's new-array execute may run on the arrays in double precision: every array
  // aligned as the planned buffer, which FFTW requires.
  bool runs_in_place(const double* in, const double* out) const {
    return fftw_alignment_of(const_cast<double*>(in)) == planned_alignment_ &&
           (out == nullptr || fftw_alignment_of(const_cast<double*>(out)) == planned_alignment_);
  }

  // The mode (i, j) times m(i, min(j, ny - j)): the multiplier's quarter read twice.
  void multiply(const EvenMultiplier& m) {
    auto* s = reinterpret_cast<std::complex<Real>*>(spectrum_.data());
    for (std::ptrdiff_t j = 0; j < ny_; ++j) {
      const double* row = m.values.data() + std::min(j, ny_ - j) * hx_;
      std::complex<Real>* modes = s + j * hx_;
      for (std::ptrdiff_t i = 0; i < hx_; ++i) modes[i] *= static_cast<Real>(row[i]);
    }
  }

  std::ptrdiff_t nx_, ny_, hx_;
  std::size_t n_real_;
  FftwBuffer<Real> field_;
  FftwBuffer<Complex> spectrum_;
  int threads_;
  int planned_alignment_ = 0;  // fftw_alignment_of the field buffer the plans were made on
  Plan forward_, inverse_;
};

}  // namespace

std::shared_ptr<SpectralFilter> SpectralFilter::create(const Grid& grid, Planning planning,
                                                       Precision precision, int threads) {
  if (precision == Precision::single)
    return std::make_shared<BasicSpectralFilter<float>>(grid, planning, threads);
  return std::make_shared<BasicSpectralFilter<double>>(grid, planning, threads);
}

}  // namespace coatfft::detail
