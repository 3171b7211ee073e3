#include "convolution/fft/detail/fftw_plan.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <type_traits>

#include "core/detail/huge_pages.hpp"
#include "core/detail/parse_name.hpp"
#include "core/error.hpp"

namespace coatfft {

std::string_view to_string(Planning planning) {
  return planning == Planning::measure ? "measure" : "estimate";
}

Planning parse_planning(std::string_view name) {
  return detail::parse_name(name, std::array{Planning::estimate, Planning::measure});
}

std::string_view to_string(Precision precision) {
  return precision == Precision::single ? "single" : "double";
}

unsigned fftw_flags(Planning planning) {
  return planning == Planning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
}

std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

bool import_fftw_wisdom(const std::string& text) {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  // Wisdom of threaded plans names the threads planner, which exists only after
  // fftw_init_threads: without it FFTW refuses the whole file.
  detail::set_planner_threads_locked(1);
  return fftw_import_wisdom_from_string(text.c_str()) != 0;
}

std::string export_fftw_wisdom() {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  char* text = fftw_export_wisdom_to_string();
  if (text == nullptr) throw Error("FFTW: fftw_export_wisdom_to_string failed");
  std::string result(text);
  fftw_free(text);
  return result;
}

void forget_fftw_wisdom() {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_forget_wisdom();
}

bool load_fftw_wisdom(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return in.good() && import_fftw_wisdom(text.str());
}

void save_fftw_wisdom(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  COATFFT_REQUIRE(!fs::exists(status) || fs::is_regular_file(status), "save_fftw_wisdom: '", path,
                  "' exists and is not a regular file");
  const std::string temporary = detail::concat(path, ".partial-", ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << export_fftw_wisdom();
    COATFFT_REQUIRE(out.good(), "save_fftw_wisdom: cannot write '", temporary, "'");
  }
  fs::rename(temporary, path, ec);
  if (ec) fs::remove(temporary);
  COATFFT_REQUIRE(!ec, "save_fftw_wisdom: cannot write the wisdom file '", path,
                  "': ", ec.message());
}

namespace detail {
void set_planner_threads_locked(int threads) {
  COATFFT_REQUIRE(threads >= 1, "FFTW plan: threads = ", threads, ", but threads must be >= 1");
  // fftw_init_threads must precede the first threaded plan; doing it lazily under the planner
  // mutex keeps it once-only without a separate init call that users could forget.
  static bool initialised = false;
  if (!initialised) {
    if (fftw_init_threads() == 0) throw Error("FFTW: fftw_init_threads failed");
    initialised = true;
  }
  fftw_plan_with_nthreads(threads);
}

void set_single_planner_threads_locked(int threads) {
  COATFFT_REQUIRE(threads >= 1, "FFTW plan: threads = ", threads, ", but threads must be >= 1");
  static bool initialised = false;  // as above, for FFTW's single-precision library
  if (!initialised) {
    if (fftwf_init_threads() == 0) throw Error("FFTW: fftwf_init_threads failed");
    initialised = true;
  }
  fftwf_plan_with_nthreads(threads);
}
}  // namespace detail

template <typename T>
FftwBuffer<T>::FftwBuffer(std::size_t size) : size_(size) {
  if (size == 0) return;
  if constexpr (std::is_same_v<T, double>) {
    data_ = fftw_alloc_real(size);
  } else if constexpr (std::is_same_v<T, fftw_complex>) {
    data_ = fftw_alloc_complex(size);
  } else if constexpr (std::is_same_v<T, float>) {
    data_ = fftwf_alloc_real(size);
  } else {
    data_ = fftwf_alloc_complex(size);
  }
  if (data_ == nullptr) throw std::bad_alloc();
  const std::size_t bytes = size * sizeof(T);
  // Large FFT buffers are walked column-wise (y transforms): with 4 KiB pages every row is
  // another page and the TLB thrashes.
  detail::advise_huge_pages(data_, bytes);
  // Zero-filled so that a buffer is never read uninitialised (and padding starts as zeros).
  std::memset(static_cast<void*>(data_), 0, bytes);
}

template <typename T>
FftwBuffer<T>::~FftwBuffer() {
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, fftw_complex>) {
    fftw_free(data_);
  } else {
    fftwf_free(data_);
  }
}

template class FftwBuffer<double>;
template class FftwBuffer<fftw_complex>;
template class FftwBuffer<float>;
template class FftwBuffer<fftwf_complex>;

template <typename Plan>
BasicFftwPlan<Plan>::BasicFftwPlan(Plan plan) : plan_(plan) {
  if (plan_ == nullptr)
    throw Error("FFTW: the planner returned no plan for the requested transform");
}

template <typename Plan>
void BasicFftwPlan<Plan>::reset() {
  if (plan_ == nullptr) return;
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  if constexpr (std::is_same_v<Plan, fftw_plan>) {
    fftw_destroy_plan(plan_);
  } else {
    fftwf_destroy_plan(plan_);
  }
  plan_ = nullptr;
}

template class BasicFftwPlan<fftw_plan>;
template class BasicFftwPlan<fftwf_plan>;

}  // namespace coatfft
