#pragma once
// Large arrays on transparent huge pages (2 MiB). A field of 2048^2 cells spans 8192 pages of
// 4 KiB: each is faulted in on its first touch (about 3 ms a MiB measured on the development
// machine, 100 ms for such a field, three operator applications) and takes a TLB entry when
// walked column-wise by the y transforms. Advised before its first touch, the same field is
// faulted in as 16 huge pages (9 ms). The kernel may decline (THP "never", or no free huge
// page), which only costs speed.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

namespace coatfft::detail {

// Arrays smaller than this are not worth a system call.
inline constexpr std::size_t kHugePageAdviceBytes = std::size_t{4} << 20;

// Advises the whole pages of [data, data + bytes) to be huge pages; call before the first touch.
inline void advise_huge_pages(void* data, std::size_t bytes) {
  if (data == nullptr || bytes < kHugePageAdviceBytes) return;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t page = 4096;
  const std::uintptr_t first = (begin + page - 1) / page * page;
  const std::uintptr_t last = (begin + bytes) / page * page;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

// An Eigen array of the given shape, allocated and advised but not yet touched (its values are
// unset, as Eigen's own sized constructor leaves them).
template <class Array>
Array untouched_array(std::ptrdiff_t rows, std::ptrdiff_t cols) {
  Array a(rows, cols);
  advise_huge_pages(a.data(), static_cast<std::size_t>(a.size()) * sizeof(typename Array::Scalar));
  return a;
}

// The same, zeroed (after the advice: the zeros are its first touch).
template <class Array>
Array zeroed_array(std::ptrdiff_t rows, std::ptrdiff_t cols) {
  Array a = untouched_array<Array>(rows, cols);
  a.setZero();
  return a;
}

}  // namespace coatfft::detail
