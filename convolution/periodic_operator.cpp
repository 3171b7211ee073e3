#include "convolution/periodic_operator.hpp"

#include <algorithm>

#include "convolution/fftw_plan.hpp"
#include "core/error.hpp"

namespace coatfft {

struct PeriodicOperator::Transforms {
  FftwRealBuffer field;
  FftwComplexBuffer spectrum;
  FftwPlan forward, inverse;
};

PeriodicOperator::~PeriodicOperator() = default;

PeriodicOperator::PeriodicOperator(const Grid& grid, const Field& kernel, Method method,
                                   Planning planning)
    : grid_(grid),
      method_(method),
      t_(std::make_unique<Transforms>(
          Transforms{FftwRealBuffer(static_cast<std::size_t>(grid.nx() * grid.ny())),
                     FftwComplexBuffer(static_cast<std::size_t>((grid.nx() / 2 + 1) * grid.ny())),
                     {},
                     {}})) {
  COATFFT_REQUIRE(kernel.rows() == grid.nx() && kernel.cols() == grid.ny(),
                  "PeriodicOperator: the kernel is not of the grid's shape");
  COATFFT_REQUIRE(kernel.allFinite(),
                  "PeriodicOperator: the kernel has a value that is not finite");
  const int nx = static_cast<int>(grid.nx()), ny = static_cast<int>(grid.ny());
  const unsigned flags = fftw_flags(planning);
  t_->forward = FftwPlan::create(1, [&] {
    return fftw_plan_dft_r2c_2d(ny, nx, t_->field.data(), t_->spectrum.data(), flags);
  });
  t_->inverse = FftwPlan::create(1, [&] {
    return fftw_plan_dft_c2r_2d(ny, nx, t_->spectrum.data(), t_->field.data(), flags);
  });
  // The kernel's spectrum, normalised by the cell count for the round trip.
  std::copy(kernel.data(), kernel.data() + kernel.size(), t_->field.data());
  t_->forward.execute();
  const double scale = 1.0 / static_cast<double>(kernel.size());
  multiplier_.resize((grid.nx() / 2 + 1) * grid.ny());
  for (std::size_t n = 0; n < multiplier_.size(); ++n)
    multiplier_[n] = scale * as_complex(t_->spectrum.data())[n].real();
}

void PeriodicOperator::apply(const Field& pressure, Field& displacement) {
  COATFFT_REQUIRE(pressure.rows() == grid_.nx() && pressure.cols() == grid_.ny(),
                  "PeriodicOperator::apply: the pressure is not of the grid's shape");
  COATFFT_REQUIRE(&pressure != &displacement,
                  "PeriodicOperator::apply: the displacement must not alias the pressure");
  COATFFT_REQUIRE(pressure.allFinite(),
                  "PeriodicOperator::apply: the pressure has a value that is not finite");
  std::copy(pressure.data(), pressure.data() + pressure.size(), t_->field.data());
  t_->forward.execute();
  std::complex<double>* s = as_complex(t_->spectrum.data());
  for (std::size_t n = 0; n < multiplier_.size(); ++n) s[n] *= multiplier_[n];
  t_->inverse.execute();
  displacement.resize(grid_.nx(), grid_.ny());
  std::copy(t_->field.data(), t_->field.data() + displacement.size(), displacement.data());
}

}  // namespace coatfft
