#include "convolution/operators/periodic_operator.hpp"

#include <algorithm>
#include <complex>
#include <type_traits>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/detail/coarse_kernel.hpp"
#include "core/error.hpp"

namespace coatfft {

// The circular convolution in one precision: the field's r2c transform, the kernel's spectrum as
// a real multiplier, the c2r transform. Fields enter and leave as double; with Real = float only
// the transforms and the product run in single precision.
struct PeriodicOperator::Transforms {
  virtual ~Transforms() = default;
  virtual void apply(const double* in, double* out) = 0;
};

namespace {

template <typename Real>
class SpectralFilter final : public PeriodicOperator::Transforms {
 public:
  static constexpr bool is_double = std::is_same_v<Real, double>;
  using Complex = std::conditional_t<is_double, fftw_complex, fftwf_complex>;
  using Plan = BasicFftwPlan<std::conditional_t<is_double, fftw_plan, fftwf_plan>>;

  SpectralFilter(const Grid& grid, Planning planning, int threads)
      : n_real_(static_cast<std::size_t>(grid.nx() * grid.ny())),
        n_complex_(static_cast<std::size_t>((grid.nx() / 2 + 1) * grid.ny())),
        field_(n_real_),
        spectrum_(n_complex_),
        multiplier_(n_complex_, Real(1)) {
    // Row-major dimensions {ny, nx}: a Field (x fastest) is a C-order (ny, nx) array.
    const int nx = static_cast<int>(grid.nx()), ny = static_cast<int>(grid.ny());
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
    if constexpr (is_double) planned_alignment_ = fftw_alignment_of(field_.data());
  }

  // The real part of the spectrum of `in` times `scale` (the even kernel's real spectrum).
  std::vector<double> real_spectrum(const double* in, double scale) {
    std::copy_n(in, n_real_, field_.data());
    forward_.execute();
    std::vector<double> out(n_complex_);
    const auto* s = reinterpret_cast<const std::complex<Real>*>(spectrum_.data());
    for (std::size_t n = 0; n < n_complex_; ++n) out[n] = scale * static_cast<double>(s[n].real());
    return out;
  }

  // In double precision apply() transforms the caller's fields themselves: the field buffer,
  // needed only for planning and real_spectrum(), is freed (a field's memory, 134 MB at 4096^2),
  // and allocated again only if a caller's field is aligned otherwise.
  void release_field() {
    if constexpr (is_double) field_ = FftwBuffer<Real>();
  }

  void set_multiplier(const std::vector<double>& multiplier) {
    std::transform(multiplier.begin(), multiplier.end(), multiplier_.begin(),
                   [](double m) { return static_cast<Real>(m); });
  }

  // In double precision the transforms read `in` and write `out` themselves (FFTW's new-array
  // execute: an out-of-place r2c keeps its input, and the c2r consumes only the spectrum), which
  // spares two copies of the field, a third of an application's memory traffic at large N; only
  // where an array's alignment differs from the planned buffer's (which FFTW requires equal) do
  // they go through field_. In single precision the copies are the conversions.
  void apply(const double* in, double* out) override {
    auto* s = reinterpret_cast<std::complex<Real>*>(spectrum_.data());
    if constexpr (is_double) {
      if (fftw_alignment_of(const_cast<double*>(in)) == planned_alignment_ &&
          fftw_alignment_of(out) == planned_alignment_) {
        fftw_execute_dft_r2c(forward_.get(), const_cast<double*>(in), spectrum_.data());
        for (std::size_t n = 0; n < n_complex_; ++n) s[n] *= multiplier_[n];
        fftw_execute_dft_c2r(inverse_.get(), spectrum_.data(), out);
        return;
      }
    }
    if (field_.size() == 0) field_ = FftwBuffer<Real>(n_real_);  // FFTW's allocator: same alignment
    std::copy_n(in, n_real_, field_.data());
    forward_.execute();
    for (std::size_t n = 0; n < n_complex_; ++n) s[n] *= multiplier_[n];
    inverse_.execute();
    std::copy_n(field_.data(), n_real_, out);
  }

 private:
  std::size_t n_real_;
  std::size_t n_complex_;
  FftwBuffer<Real> field_;
  int planned_alignment_ = 0;  // fftw_alignment_of the field buffer the plans were made on
  FftwBuffer<Complex> spectrum_;
  Plan forward_, inverse_;
  std::vector<Real> multiplier_;
};

}  // namespace

PeriodicOperator::~PeriodicOperator() = default;

PeriodicOperator::PeriodicOperator(const Grid& grid, const Field& kernel, Method method,
                                   Planning planning, Precision precision, int threads)
    : grid_(grid), method_(method), precision_(precision), threads_(threads) {
  COATFFT_REQUIRE(kernel.rows() == grid.nx() && kernel.cols() == grid.ny(),
                  "PeriodicOperator: the kernel is not of the grid's shape");
  COATFFT_REQUIRE(kernel.allFinite(),
                  "PeriodicOperator: the kernel has a value that is not finite");
  // The kernel's spectrum in double precision, normalised by the cell count for the round trip.
  COATFFT_REQUIRE(threads >= 1, "PeriodicOperator: threads = ", threads, " must be >= 1");
  // (Only planned with care when it is the one apply() runs.)
  const Planning exact_planning = precision == Precision::single ? Planning::estimate : planning;
  auto exact = std::make_unique<SpectralFilter<double>>(grid, exact_planning, threads);
  const std::vector<double> multiplier =
      exact->real_spectrum(kernel.data(), 1.0 / static_cast<double>(kernel.size()));
  if (precision == Precision::single) {
    auto single = std::make_unique<SpectralFilter<float>>(grid, planning, threads);
    single->set_multiplier(multiplier);
    t_ = std::move(single);
  } else {
    exact->set_multiplier(multiplier);
    exact->release_field();
    t_ = std::move(exact);
  }
}

void PeriodicOperator::apply(const Field& pressure, Field& displacement) {
  COATFFT_REQUIRE(pressure.rows() == grid_.nx() && pressure.cols() == grid_.ny(),
                  "PeriodicOperator::apply: the pressure is not of the grid's shape");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "PeriodicOperator::apply: the displacement must not alias the pressure");
  COATFFT_REQUIRE(pressure.allFinite(),
                  "PeriodicOperator::apply: the pressure has a value that is not finite");
  displacement.resize(grid_.nx(), grid_.ny());
  t_->apply(pressure.data(), displacement.data());
}

std::unique_ptr<SurfaceOperator> PeriodicOperator::coarsened() {
  if (grid_.nx() % 2 != 0 || grid_.ny() % 2 != 0) return nullptr;
  const Field kernel = unit_response();
  const Grid coarse(grid_.nx() / 2, grid_.ny() / 2, grid_.lx(), grid_.ly());
  return std::make_unique<PeriodicOperator>(coarse, detail::coarse_periodic_kernel(kernel), method_,
                                            Planning::estimate, precision_, threads_);
}

}  // namespace coatfft
