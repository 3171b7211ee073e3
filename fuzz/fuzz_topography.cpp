// libFuzzer target: coatfft::topography::read_topography on arbitrary bytes as an X3P archive
// (zip, XML, binary points), an SDF file (ASCII or binary), x y z rows or a NetCDF file (opened
// in memory by netcdf-c, nc_open_mem; NetCDF-3 only, below), the first byte choosing the format.
// InvalidArgument is the expected refusal; any other exception escapes and, like a crash or a
// sanitizer report, is a finding. netcdf-c is not instrumented here: its parsing is exercised,
// the coverage guiding the fuzzer is the reader's (docs/fuzz_report.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "topography/topography.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const coatfft::fuzz::ScratchFolder scratch("fuzz_topography");
  if (size == 0) return 0;
  static const char* const names[] = {"input.x3p", "input.sdf", "input.xyz", "input.nc"};
  // NetCDF-3 only: HDF5 1.10.8 loops without end on some damaged NetCDF-4 files, found within
  // seconds (fuzz/findings/README.md), which would end every run.
  if (data[0] % 4 == 3 &&
      (size < 4 || std::string_view(reinterpret_cast<const char*>(data + 1), 3) != "CDF"))
    return 0;
  const auto path = scratch.write(names[data[0] % 4], data + 1, size - 1);
  coatfft::topography::ReadOptions options;
  options.missing = (data[0] / 4) % 2 ? coatfft::topography::MissingPoints::fill
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
