// libFuzzer target: coatfft::io::read_npy on arbitrary bytes. InvalidArgument is the expected
// refusal; any other exception escapes and, like a crash or a sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "io/npy.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const coatfft::fuzz::ScratchFolder scratch("fuzz_npy");
  const auto path = scratch.write("input.npy", data, size);
  try {
    const coatfft::Field field = coatfft::io::read_npy(path);
    if (field.size() == 0) __builtin_trap();  // the reader promises a non-empty array
  } catch (const coatfft::InvalidArgument&) {
  }
  return 0;
}
