// libFuzzer target: coatfft::topography::read_topography on arbitrary bytes as an X3P archive
// (zip, XML, binary points), an SDF file (ASCII or binary) or x y z rows, the first byte choosing
// the format. InvalidArgument is the expected refusal; any other exception escapes and, like a
// crash or a sanitizer report, is a finding. NetCDF input is parsed by netcdf-c (and HDF5),
// which are not instrumented here (docs/fuzz_report.md).
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "topography/topography.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const coatfft::fuzz::ScratchFolder scratch("fuzz_topography");
  if (size == 0) return 0;
  static const char* const names[] = {"input.x3p", "input.sdf", "input.xyz"};
  const auto path = scratch.write(names[data[0] % 3], data + 1, size - 1);
  coatfft::topography::ReadOptions options;
  options.missing = (data[0] / 3) % 2 ? coatfft::topography::MissingPoints::fill
                                      : coatfft::topography::MissingPoints::refuse;
  options.max_bytes = std::uintmax_t{64} << 20;
  try {
    const auto t = coatfft::topography::read_topography(path, options);
    // The reader promises at least 2 x 2 finite heights.
    if (t.heights.rows() < 2 || t.heights.cols() < 2 || !t.heights.allFinite()) __builtin_trap();
  } catch (const coatfft::InvalidArgument&) {
  }
  return 0;
}
