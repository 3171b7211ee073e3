#include "cli/topography_command.hpp"

#include <cmath>
#include <iostream>

#include "cli/output_file.hpp"
#include "cli/staged_output.hpp"
#include "core/error.hpp"
#include "io/netcdf_writer.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography_summary.hpp"

namespace coatfft::cli {

namespace {
// A size given on the command line: the file's when it has none, else checked against it (to
// 1e-9, the digits a file prints).
void apply_size(std::optional<double>& size, const std::optional<double>& given, const char* flag) {
  if (!given) return;
  COATFFT_REQUIRE(std::isfinite(*given) && *given > 0, flag, " = ", *given,
                  " m must be finite and > 0");
  COATFFT_REQUIRE(!size || std::abs(*size - *given) <= 1e-9 * *size, flag, " = ", *given,
                  " m disagrees with the file's ", *size, " m");
  size = given;
}
}  // namespace

void topography_command(const TopographyOptions& o) {
  topography::ReadOptions read;
  read.unit = o.unit;
  read.missing = topography::missing_points_from_name(o.missing, "--missing");
  read.max_memory = o.max_memory;
  read.fill_hint = "--missing fill";
  const Detrend detrend = detrend_from_name(o.detrend, "--detrend");
  COATFFT_REQUIRE(o.lx.has_value() == o.ly.has_value(), "give both --lx and --ly, or neither");
  std::optional<StagedFile> file;
  std::optional<io::HeightsFormat> format;
  COATFFT_REQUIRE(!o.gap || o.output, "--gap needs -o FILE.npy");
  // The output is checked before any work: a file that cannot be written is refused at once.
  if (o.output) {
    format = io::heights_format(*o.output);
    // A NetCDF file in SurfaceTopography's layout holds heights, not a gap.
    COATFFT_REQUIRE(!o.gap || format == io::HeightsFormat::npy, "--gap: ", o.output->string(),
                    ": the gap is written as .npy (name it *.npy)");
    file.emplace(*o.output, "output file", std::vector{o.input});
    refuse_existing_output(*o.output, o.overwrite);
  }
  topography::Topography t = topography::read_topography(o.input, read);
  apply_size(t.lx, o.lx, "--lx");
  apply_size(t.ly, o.ly, "--ly");
  const Grid grid = topography::topography_grid(o.input, t);
  const Field heights = detrended(grid, t.heights, detrend);
  topography::require_finite_map(o.input, heights, "the detrended map");
  // The summary before the file: a parameter beyond the largest double is refused, writing
  // nothing.
  const std::optional<Grid> sized = t.lx ? std::optional(grid) : std::nullopt;
  const nlohmann::json summary = topography::topography_summary(o.input, t, heights, detrend, sized,
                                                                t.periodic.value_or(false));
  if (file) {
    COATFFT_REQUIRE(t.lx || format == io::HeightsFormat::npy, o.input.string(),
                    ": the file carries no size; give --lx and --ly to write a NetCDF file");
    Field gap;  // the heights are written as they are, not copied
    if (o.gap) {
      gap = gap_of_topography(heights);
      topography::require_finite_map(o.input, gap, "the gap max(z) - z");
    }
    const Field& written = o.gap ? gap : heights;
    io::write_heights(file->path(), *format, written, grid, t.periodic.value_or(false),
                      {{{"source", o.input.filename().string()}, {"format", t.format}}, {}});
    refuse_existing_output(*o.output, o.overwrite);  // made while the map was read
    file->commit();
  }
  std::cout << summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace coatfft::cli
