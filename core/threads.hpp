#pragma once
// The thread counts the library accepts, in one place.

namespace coatfft {

/// Largest `threads` option accepted by the library's parallel loops and operators: beyond the
/// core counts of the machines this library targets, a larger value is a typo rather than a
/// request, and every loop also caps its workers at its number of iterations.
inline constexpr int max_threads = 256;

}  // namespace coatfft
