#pragma once
// RAII for FFTW3 buffers and plans, and the one process-wide planner lock. FFTW's planner (plan
// creation and destruction, wisdom, fftw_plan_with_nthreads) is not thread-safe, whereas
// fftw_execute is; so every planner call in coatfft goes through fftw_planner_mutex(). Plans are
// made on owned fftw_alloc buffers and executed only on those buffers (no new-array execute), which
// rules out the alignment and in-place traps of the FFTW manual (section 4.6).
#include <fftw3.h>

#include <complex>
#include <cstddef>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>

#include "convolution/fft/fftw_wisdom.hpp"
#include "convolution/fft/planning.hpp"

namespace coatfft {

/// The FFTW planner flag for `planning` (FFTW_ESTIMATE or FFTW_MEASURE).
unsigned fftw_flags(Planning planning);

/// The mutex that serialises every FFTW planner call in the process.
std::mutex& fftw_planner_mutex();

namespace detail {
/// Calls fftw_init_threads once, then fftw_plan_with_nthreads(threads). The caller must hold
/// fftw_planner_mutex().
void set_planner_threads_locked(int threads);
/// The same for FFTW's single-precision library (fftwf_init_threads, fftwf_plan_with_nthreads).
void set_single_planner_threads_locked(int threads);
}  // namespace detail

/// An owned, SIMD-aligned FFTW array of `size` elements of T (double or fftw_complex, or float or
/// fftwf_complex for FFTW's single-precision library), zero-initialised. Move-only.
template <typename T>
class FftwBuffer {
 public:
  FftwBuffer() = default;
  explicit FftwBuffer(std::size_t size);
  ~FftwBuffer();
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
  FftwBuffer(FftwBuffer&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  FftwBuffer& operator=(FftwBuffer&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    return *this;
  }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

using FftwRealBuffer = FftwBuffer<double>;
using FftwComplexBuffer = FftwBuffer<fftw_complex>;
using FftwfRealBuffer = FftwBuffer<float>;
using FftwfComplexBuffer = FftwBuffer<fftwf_complex>;

/// View of an fftw_complex array as std::complex<double> (layout-compatible, FFTW manual 4.1.1).
inline std::complex<double>* as_complex(fftw_complex* p) {
  return reinterpret_cast<std::complex<double>*>(p);
}
inline const std::complex<double>* as_complex(const fftw_complex* p) {
  return reinterpret_cast<const std::complex<double>*>(p);
}

/// An owned fftw_plan (or fftwf_plan, FFTW's single precision). Made by create(), which runs the
/// planner call under the planner mutex with the requested number of FFTW threads; destroyed under
/// the same mutex. Move-only.
template <typename Plan>
class BasicFftwPlan {
 public:
  BasicFftwPlan() = default;
  ~BasicFftwPlan() { reset(); }
  BasicFftwPlan(const BasicFftwPlan&) = delete;
  BasicFftwPlan& operator=(const BasicFftwPlan&) = delete;
  BasicFftwPlan(BasicFftwPlan&& other) noexcept : plan_(std::exchange(other.plan_, nullptr)) {}
  BasicFftwPlan& operator=(BasicFftwPlan&& other) noexcept {
    std::swap(plan_, other.plan_);
    return *this;
  }

  /// Calls `make()` (an fftw_plan_* call returning the plan) under the planner mutex after
  /// setting `threads` (>= 1) planner threads. Throws Error when FFTW returns no plan.
  template <typename Make>
  static BasicFftwPlan create(int threads, Make&& make) {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    if constexpr (std::is_same_v<Plan, fftw_plan>) {
      detail::set_planner_threads_locked(threads);
    } else {
      detail::set_single_planner_threads_locked(threads);
    }
    return BasicFftwPlan(std::forward<Make>(make)());
  }

  /// Executes the plan on the buffers it was made on.
  void execute() const {
    if constexpr (std::is_same_v<Plan, fftw_plan>) {
      fftw_execute(plan_);
    } else {
      fftwf_execute(plan_);
    }
  }
  bool valid() const { return plan_ != nullptr; }
  Plan get() const { return plan_; }

 private:
  explicit BasicFftwPlan(Plan plan);
  void reset();

  Plan plan_ = nullptr;
};

using FftwPlan = BasicFftwPlan<fftw_plan>;
using FftwfPlan = BasicFftwPlan<fftwf_plan>;

}  // namespace coatfft
