#pragma once
// Whether this test program is built with AddressSanitizer, whose shadow memory reserves terabytes
// of address space: a test that bounds a child's address space (RLIMIT_AS, prlimit --as) cannot
// run it there, and leaves that bound to the Release pass.

namespace coatfft_test {

inline bool address_sanitized() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
  return __has_feature(address_sanitizer);
#else
  return false;
#endif
}

}  // namespace coatfft_test
